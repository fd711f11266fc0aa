#include <fmt/format.h>
#include <fstream>
#include <iostream>

#include "commands.h"
#include "kind_registry.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::app {

namespace {
void write_output(const std::string& text, const std::string& output_path) {
  if (output_path.empty()) {
    std::cout << text;
    return;
  }
  std::ofstream out(output_path);
  if (!out) throw InputError(fmt::format("-o {}: cannot write the output file", output_path));
  out << text;
}
}  // namespace

int run_command(const std::string& case_path, const std::string& output_path) {
  const auto case_json = model::read_json_file(case_path);
  try {
    write_output(run_case(case_json).dump(2) + "\n", output_path);
  } catch (const ConvergenceError& e) {
    // The diagnostics of an unconverged solve go where output was asked for (a file only:
    // stdout stays empty on failure), then the failure is reported.
    if (!e.diagnostics.empty() && !output_path.empty()) write_output(e.diagnostics + "\n", output_path);
    throw;
  }
  return exit_ok;
}

}  // namespace gearbench::app
