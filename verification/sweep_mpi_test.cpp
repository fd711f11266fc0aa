// `gearbench sweep` under mpiexec: the table is the same with 1 and 2 ranks as without MPI
// (each case depends only on its index; rows are gathered and written in index order).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include "support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// Runs the sweep with `launcher` ("" or "mpiexec -n N ...") into dir/name; exit code.
int run_sweep(const fs::path& dir, const std::string& launcher, const std::string& name) {
  // OpenMPI refuses to start as root unless told that it is meant (CI runs as root).
  const std::string env = ::geteuid() == 0 ? "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " : "";
  const std::string command = env + launcher + " '" + GEARBENCH_EXE + "' sweep '" + (dir / "sweep.json").string() +
                              "' --out '" + (dir / name).string() + "' >'" + (dir / (name + ".log")).string() +
                              "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(SweepMpi, SameTableForOneAndTwoRanks) {
  const auto dir = gearbench::testing_support::temp_path("sweep_mpi");
  fs::remove_all(dir);
  fs::create_directories(dir);
  // 3 × 3 geometry and efficiency figures with one failing case (teeth 5 is below the
  // minimum): odd counts so that the ranks get unequal shares.
  std::ofstream(dir / "sweep.json") << json{
      {"base", GEARBENCH_SOURCE_DIR "/cases/seed004_spur_efficiency.json"},
      {"vary", {{"gear_pair.teeth.0", {5, 22, 25}}, {"operating.pinion_torque_Nm", {50, 100, 150}}}},
      {"outputs", {"efficiency_mean", "power_loss_mean_W", "loss_factor_numeric"}}}.dump();
  const std::string mpiexec = std::string("'") + MPIEXEC + "' --oversubscribe -n ";
  ASSERT_EQ(run_sweep(dir, "", "serial"), 1) << slurp(dir / "serial.log");  // a case failed
  ASSERT_EQ(run_sweep(dir, mpiexec + "1", "one"), 1) << slurp(dir / "one.log");
  ASSERT_EQ(run_sweep(dir, mpiexec + "2", "two"), 1) << slurp(dir / "two.log");
  const std::string serial = slurp(dir / "serial" / "sweep.csv");
  EXPECT_EQ(std::count(serial.begin(), serial.end(), '\n'), 10);  // header + 9 cases
  EXPECT_EQ(slurp(dir / "one" / "sweep.csv"), serial);
  EXPECT_EQ(slurp(dir / "two" / "sweep.csv"), serial);
  const auto rows = [&](const char* name) { return json::parse(slurp(dir / name / "sweep.json"))["rows"]; };
  EXPECT_EQ(rows("two"), rows("serial"));
  const auto two = json::parse(slurp(dir / "two" / "sweep.json"));
  EXPECT_EQ(two["timing"]["ranks"], 2);
  std::set<int> ranks;
  for (const auto& t : two["timing"]["cases"]) ranks.insert(t["rank"].get<int>());
  EXPECT_EQ(ranks, (std::set<int>{0, 1}));  // both ranks did work
  EXPECT_NE(slurp(dir / "two.log").find("rank 1"), std::string::npos);  // progress from rank 1
  fs::remove_all(dir);
}

}  // namespace
