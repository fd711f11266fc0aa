// `gearbench schema [KIND]`: the JSON Schema of a kind's case files, or of all kinds.
#include <iostream>

#include "case_schema.h"
#include "commands.h"

namespace gearbench::app {

int schema_command(const std::string& kind_name) {
  if (kind_name.empty()) {
    std::cout << all_kinds_schema().dump(2) << "\n";
    return exit_ok;
  }
  std::cout << kind_schema(KindRegistry::instance().find(kind_name)).dump(2) << "\n";
  return exit_ok;
}

}  // namespace gearbench::app
