// `gearbench schema [KIND]`: the JSON Schema of a kind's case files, or of all kinds.
#include <fmt/format.h>
#include <iostream>

#include "case_schema.h"
#include "commands.h"
#include "model/errors.h"

namespace gearbench::app {

int schema_command(const std::string& kind_name) {
  if (kind_name.empty()) {
    std::cout << all_kinds_schema().dump(2) << "\n";
    return exit_ok;
  }
  const auto& kind = KindRegistry::instance().find(kind_name);
  const auto schema = kind_schema(kind);
  // A schema made up by hand could disagree with the reader; none is printed instead.
  if (!schema)
    throw InputError(fmt::format("kind {}: has no schema yet: its keys are read by hand, not from an Options table "
                                 "(issue 21); `gearbench schema` lists the kinds that have one",
                                 kind_name));
  std::cout << schema->dump(2) << "\n";
  return exit_ok;
}

}  // namespace gearbench::app
