#pragma once
// Parts of gearbench built as plugins: shared objects loaded on first use, so that a program
// starts without their heavy dependencies (the FE tooth reference's deal.II and gmsh stack).
// A plugin sits next to the executable that loads it, where the build writes it; programs
// elsewhere in the build tree (tests, benchmarks) find it at the path the build gave it.
#include <stdexcept>
#include <string>

namespace gearbench {

/// A plugin is missing or does not load; the message names the file and where it was
/// looked for. CLI exit code 1 (the input is fine; the installation is not).
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PluginLocation {
  std::string file;        ///< file name, looked for next to the running executable
  std::string build_path;  ///< where the build wrote it
  std::string purpose;     ///< what needs it, for the error message
};

/// The address of `symbol` in the plugin, loaded on first call and never unloaded. Every
/// dependency is resolved at load time (RTLD_NOW), so a broken installation fails here
/// rather than in the middle of a solve. PluginError naming the paths looked at, or the
/// loader's reason, when the plugin cannot be used.
void* plugin_symbol(const PluginLocation& plugin, const char* symbol);

}  // namespace gearbench
