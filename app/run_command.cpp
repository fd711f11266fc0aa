#include <chrono>
#include <condition_variable>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
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

namespace fs = std::filesystem;

/// Writes `text` to `path` as it is, for what cannot be replaced: a device, a pipe, a
/// dangling symbolic link. Messages name `output_path`, the path as given to -o.
void write_through(const std::string& path, const std::string& text, const std::string& output_path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(fmt::format("-o {}: cannot write the output file", model::shown_text(output_path)));
  out << text;
  out.flush();
  if (!out) throw OutputError(fmt::format("-o {}: writing the output failed: {}", model::shown_text(output_path),
                                          std::strerror(errno)));
}

/// A temporary file next to `path`, then a rename: the file never holds half a result.
void replace_atomically(const fs::path& path, const std::string& text, const std::string& output_path) {
  const std::string temp = path.string() + ".tmp-" + std::to_string(::getpid());
  try {
    write_through(temp, text, output_path);
  } catch (...) {
    std::remove(temp.c_str());
    throw;
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temp.c_str());
    throw OutputError(fmt::format("-o {}: writing the output failed: {}", model::shown_text(output_path),
                                  std::strerror(error)));
  }
}

/// `-o`: a regular file (through any symbolic links to it) or a new path is replaced
/// atomically; a device or pipe (/dev/null, /dev/stdout) is written through, never renamed
/// over; a directory is refused.
void write_output(const std::string& text, const std::string& output_path) {
  if (output_path.empty()) {
    std::cout << text;  // main checks that stdout took it
    return;
  }
  // The result is the run's last step: a Ctrl-C from here on waits for the end of the run, as
  // verify holds it for its report. Deferred only to the end of this function, a signal that
  // came during the write ended the run with 130 after the file had been renamed into place.
  hold_interrupts_to_the_end();
  std::error_code ec;
  const auto status = fs::status(output_path, ec);
  if (fs::is_directory(status))
    throw InputError(fmt::format("-o {}: is a directory; name the file to write the result to",
                                 model::shown_text(output_path)));
  if (fs::is_regular_file(status))
    replace_atomically(fs::canonical(output_path), text, output_path);
  else if (!fs::exists(status) && !fs::is_symlink(fs::symlink_status(output_path, ec)))
    replace_atomically(output_path, text, output_path);
  else
    write_through(output_path, text, output_path);
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
    // How the solve went, in one line (a result's summary(), as Ceres' BriefReport).
    if (const auto it = result.find("summary"); it != result.end() && it->is_string())
      std::cerr << "gearbench: " << it->get<std::string>() << std::endl;
  } catch (const ConvergenceError& e) {
    // The diagnostics of an unconverged solve go where output was asked for (a file only:
    // stdout stays empty on failure), then the failure is reported.
    if (!e.diagnostics.empty() && !output_path.empty()) write_output(e.diagnostics + "\n", output_path);
    throw;
  }
  return exit_ok;
}

}  // namespace gearbench::app
