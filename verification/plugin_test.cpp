// The plugin loader (solvers/model/plugin.h): what it says when a plugin cannot be used. The
// plugins themselves are exercised by every FE test and the MPI sweep test.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "model/plugin.h"
#include "support/temp_dir.h"

namespace gearbench {
namespace {

namespace fs = std::filesystem;

std::string error_of(const PluginLocation& plugin, const char* symbol) {
  try {
    plugin_symbol(plugin, symbol);
  } catch (const PluginError& e) {
    return e.what();
  }
  return "";
}

TEST(Plugin, AbsentNamesWhereItLookedAndHowToBuildIt) {
  const auto message = error_of({"libgearbench_absent.so", "/nonexistent/build/libgearbench_absent.so",
                                 "the absent reference"}, "entry");
  EXPECT_NE(message.find("the absent reference needs the plugin libgearbench_absent.so"), std::string::npos) << message;
  EXPECT_NE(message.find("/nonexistent/build/libgearbench_absent.so"), std::string::npos) << message;
  // The first place looked at: next to this test's executable.
  EXPECT_NE(message.find(fs::read_symlink("/proc/self/exe").parent_path().string() + "/libgearbench_absent.so"),
            std::string::npos) << message;
  EXPECT_NE(message.find("cmake --build"), std::string::npos) << message;
}

TEST(Plugin, PresentButNotLoadableIsReportedNotSkipped) {
  const auto path = gearbench::testing_support::temp_path("plugin.so");
  std::ofstream(path) << "not a shared object\n";
  const auto message = error_of({path.filename().string(), path.string(), "the broken reference"}, "entry");
  fs::remove(path);
  EXPECT_NE(message.find("which does not load"), std::string::npos) << message;
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
}

TEST(Plugin, MissingEntryPointIsNamed) {
  // Any shared object will do: the one holding cos.
  Dl_info libm{};
  ASSERT_NE(::dladdr(reinterpret_cast<void*>(static_cast<double (*)(double)>(&::cos)), &libm), 0);
  const fs::path path = libm.dli_fname;
  const auto message = error_of({path.filename().string(), path.string(), "the maths"}, "gearbench_no_such_entry");
  EXPECT_NE(message.find("has no entry point gearbench_no_such_entry"), std::string::npos) << message;
}

}  // namespace
}  // namespace gearbench
