#include "fe_backend.h"

#include "model/plugin.h"

namespace gearbench::reference::fe {
namespace {

const FeBackend& load() {
  const PluginLocation plugin{GEARBENCH_FE_BACKEND_FILE, GEARBENCH_FE_BACKEND_BUILD_PATH,
                              "the finite-element tooth reference (deal.II)"};
  const auto entry = reinterpret_cast<decltype(&gearbench_fe_backend)>(plugin_symbol(plugin, "gearbench_fe_backend"));
  const FeBackend& backend = *entry();
  if (backend.layout != backend_layout())
    throw PluginError(plugin.purpose + ": the plugin " + plugin.file +
                      " was built from other sources than this program; rebuild both (cmake --build --preset default)");
  return backend;
}

}  // namespace

const FeBackend& fe_backend() {
  static const FeBackend& backend = load();
  return backend;
}

}  // namespace gearbench::reference::fe
