#pragma once
// Helpers shared by `gearbench bench` and `gearbench bench --commits`: shell commands, git
// commit times, and record files that are never overwritten and never half-written.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace gearbench::app {

/// Runs `command` through the shell; its standard output (stderr is left alone) and exit code.
struct CommandResult {
  int exit_code = -1;
  std::string out;
};
CommandResult capture(const std::string& command);

/// `text` quoted for the shell (single quotes, embedded ones escaped).
std::string shell_quoted(const std::string& text);

/// Commit time of `sha` in the git checkout `repo` as "YYYY-MM-DDTHH:MM:SSZ", or "" when git
/// cannot tell (no git, not a checkout, unknown sha). Orders records by commit, not by
/// when they were recorded.
std::string commit_time_utc(const std::string& repo, const std::string& sha);

/// out_dir/<stem>.json, or <stem>-2.json, -3, ... when taken: a record is never overwritten.
std::filesystem::path free_path(const std::filesystem::path& out_dir, const std::string& stem);

/// Writes `record` to `target` through a temporary file, interrupts held: the record
/// appears whole or not at all.
void write_record(const std::filesystem::path& target, const nlohmann::json& record);

}  // namespace gearbench::app
