#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <mutex>
#include <thread>
#include <unistd.h>

#include "commands.h"
#include "interrupt.h"
#include "kind_registry.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::app {

namespace {
void write_output(const std::string& text, const std::string& output_path) {
  if (output_path.empty()) {
    std::cout << text;
    return;
  }
  // A temporary file next to the target, then a rename: -o never holds half a result.
  const DeferInterrupts defer;
  const std::string temp = output_path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temp);
    if (!out) throw InputError(fmt::format("-o {}: cannot write the output file", output_path));
    out << text;
    out.flush();
    if (!out) {
      std::remove(temp.c_str());
      throw std::runtime_error(fmt::format("-o {}: writing the output failed", output_path));
    }
  }
  if (std::rename(temp.c_str(), output_path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw std::runtime_error(fmt::format("-o {}: writing the output failed", output_path));
  }
}
}  // namespace

/// Says on stderr that a solve is under way once it has run for a second, and how long it
/// took when it ends; silent for quick runs.
class ProgressNotice {
 public:
  explicit ProgressNotice(std::string what) : what_(std::move(what)), start_(std::chrono::steady_clock::now()) {
    watcher_ = std::thread([this] {
      std::unique_lock lock(mutex_);
      if (!done_cv_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; })) {
        std::cerr << "gearbench: " << what_ << " running..." << std::endl;
        announced_ = true;
      }
    });
  }
  ~ProgressNotice() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    done_cv_.notify_all();
    watcher_.join();
    if (announced_)
      std::cerr << fmt::format("gearbench: {} finished in {:.1f} s", what_,
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count())
                << std::endl;
  }

 private:
  std::string what_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = false;
  bool announced_ = false;
  std::thread watcher_;
};

int run_command(const std::string& case_path, const std::string& output_path) {
  const auto case_json = model::read_json_file(case_path);
  try {
    const std::string kind = case_json.is_object() && case_json.contains("kind") && case_json["kind"].is_string()
                                 ? case_json["kind"].get<std::string>() : std::string("case");
    nlohmann::json result;
    {
      const ProgressNotice notice(fmt::format("{} ({})", case_path, kind));
      result = run_case(case_json);
    }
    write_output(result.dump(2) + "\n", output_path);
  } catch (const ConvergenceError& e) {
    // The diagnostics of an unconverged solve go where output was asked for (a file only:
    // stdout stays empty on failure), then the failure is reported.
    if (!e.diagnostics.empty() && !output_path.empty()) write_output(e.diagnostics + "\n", output_path);
    throw;
  }
  return exit_ok;
}

}  // namespace gearbench::app
