#include "bench_support.h"

#include <array>
#include <cstdio>
#include <ctime>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <sys/wait.h>

#include "interrupt.h"

namespace gearbench::app {

namespace fs = std::filesystem;

CommandResult capture(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string commit_time_utc(const std::string& repo, const std::string& sha) {
  if (sha.empty() || sha == "unknown") return "";
  const auto git = capture(fmt::format("git -C {} log -1 --format=%ct {} 2>/dev/null", shell_quoted(repo),
                                       shell_quoted(sha)));
  char* end = nullptr;
  const std::time_t t = std::strtoll(git.out.c_str(), &end, 10);
  if (git.exit_code != 0 || end == git.out.c_str()) return "";
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::array<char, 32> out{};
  std::strftime(out.data(), out.size(), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return out.data();
}

fs::path free_path(const fs::path& out_dir, const std::string& stem) {
  fs::path target = out_dir / (stem + ".json");
  for (int suffix = 2; fs::exists(target); ++suffix) target = out_dir / fmt::format("{}-{}.json", stem, suffix);
  return target;
}

void write_record(const fs::path& target, const nlohmann::json& record) {
  const DeferInterrupts defer;
  const auto temp = fs::path(target.string() + ".tmp");
  std::ofstream out(temp);
  out << record.dump(2) << "\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + temp.string());
  fs::rename(temp, target);
}

}  // namespace gearbench::app
