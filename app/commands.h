#pragma once
// The subcommands of the gearbench CLI. Each returns the process exit code.
#include <string>

namespace gearbench::app {

/// Exit codes of the CLI contract.
enum ExitCode : int {
  exit_ok = 0,
  exit_failed = 1,         ///< a verification check failed / a regression was found
  exit_bad_input = 2,      ///< InputError
  exit_not_converged = 3,  ///< ConvergenceError
};

int run_command(const std::string& case_path, const std::string& output_path);
int verify_command(const std::string& tier, const std::string& out_dir, const std::string& cases_dir,
                   const std::string& bench_record);
int report_compare_command(const std::string& before, const std::string& after);
int bench_command(const std::string& out_dir, const std::string& filter, double min_time);

/// Where `verify` and `bench` write unless told otherwise: an ignored folder of the checkout.
std::string default_output_dir();
std::string default_cases_dir();

}  // namespace gearbench::app
