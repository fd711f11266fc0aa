#include <fmt/format.h>
#include <fstream>
#include <iostream>

#include "commands.h"
#include "kind_registry.h"
#include "model/errors.h"
#include "model/json_reader.h"

namespace gearbench::app {

int run_command(const std::string& case_path, const std::string& output_path) {
  const auto case_json = model::read_json_file(case_path);
  const auto result = run_case(case_json);
  const std::string text = result.dump(2) + "\n";
  if (output_path.empty()) {
    std::cout << text;
  } else {
    std::ofstream out(output_path);
    if (!out) throw InputError(fmt::format("-o {}: cannot write the output file", output_path));
    out << text;
  }
  return exit_ok;
}

}  // namespace gearbench::app
