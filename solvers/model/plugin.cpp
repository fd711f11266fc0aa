#include "plugin.h"

#include <dlfcn.h>

#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <vector>

namespace gearbench {
namespace {

namespace fs = std::filesystem;

/// Next to the running executable (/proc/self/exe: wherever it was started from, through
/// any symbolic link), then the build tree.
std::vector<fs::path> candidates(const PluginLocation& plugin) {
  std::vector<fs::path> paths;
  std::error_code ec;
  if (const auto exe = fs::read_symlink("/proc/self/exe", ec); !ec) paths.push_back(exe.parent_path() / plugin.file);
  if (paths.empty() || paths.front() != fs::path(plugin.build_path)) paths.emplace_back(plugin.build_path);
  return paths;
}

}  // namespace

void* plugin_symbol(const PluginLocation& plugin, const char* symbol) {
  const auto paths = candidates(plugin);
  for (const auto& path : paths) {
    if (!fs::exists(path)) continue;
    // A plugin that is there but does not load is reported, not skipped: the next one
    // found would hide a broken installation.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
      throw PluginError(fmt::format("{} needs the plugin {}, which does not load: {}", plugin.purpose,
                                    path.string(), ::dlerror()));
    void* entry = ::dlsym(handle, symbol);
    if (entry == nullptr)
      throw PluginError(fmt::format("{} needs the plugin {}, which has no entry point {}", plugin.purpose,
                                    path.string(), symbol));
    return entry;
  }
  std::vector<std::string> looked;
  for (const auto& p : paths) looked.push_back(p.string());
  throw PluginError(fmt::format("{} needs the plugin {}, which is not built (looked for {}); build it with "
                                "`cmake --build --preset default`",
                                plugin.purpose, plugin.file, fmt::join(looked, " and ")));
}

}  // namespace gearbench
