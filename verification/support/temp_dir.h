#pragma once
// A temporary directory per test process, removed at exit, and the paths in it.
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace gearbench::testing_support {

namespace fs = std::filesystem;

/// The temporary directory of this test process (ctest runs tests in parallel, and several
/// builds may test at once): emptied when first used, so that nothing an earlier process of the
/// same pid left behind is met, and removed with all it holds at exit, so that the tests leave
/// nothing in /tmp (one file per name and pid had piled up to some 20 000).
class ProcessTempDir {
 public:
  ProcessTempDir() : path_(fs::temp_directory_path() / ("gearbench-test-" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directory(path_);
  }
  ~ProcessTempDir() {
    std::error_code ignored;  // a destructor at exit must not throw
    fs::remove_all(path_, ignored);
  }
  ProcessTempDir(const ProcessTempDir&) = delete;
  ProcessTempDir& operator=(const ProcessTempDir&) = delete;

  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// A temporary path unique to this test process, in its ProcessTempDir.
inline fs::path temp_path(const std::string& name) {
  static const ProcessTempDir dir;
  return dir.path() / name;
}

}  // namespace gearbench::testing_support
