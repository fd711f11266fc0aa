// `gearbench lubricants [NAME --temperature-C T]`: the catalogue, or one oil resolved at a
// temperature, with the source of every figure.
#include <fmt/format.h>
#include <iostream>

#include "commands.h"
#include "lubricant/catalogue.h"
#include "lubricant/lubricant_section.h"
#include "lubricant/viscosity_temperature.h"
#include "model/errors.h"

namespace gearbench::app {
namespace {

using nlohmann::json;

void print_catalogue(const lubricant::Catalogue& c) {
  std::cout << "gearbench lubricant catalogue (data/lubricants.json); `gearbench lubricants NAME --temperature-C T`\n"
               "resolves one. ISO VG grades (ISO 3448 midpoint nu40) of every base: mineral, PAO, ester, PAG;\n"
               "a grade without a sourced nu100 needs {\"grade\", \"base\", \"nu100_mm2_s\"} or {\"grade\", \"base\",\n"
               "\"viscosity_index\"} (nu100 by ASTM D2270 / ISO 2909) in a case.\n\n";
  for (const auto& name : c.names()) std::cout << "  " << name << "\n";
  std::cout << "\nsources:\n";
  for (const auto& [key, text] : c.sources().items()) std::cout << "  " << key << ": " << text.get<std::string>() << "\n";
}

}  // namespace

int lubricants_command(const std::string& name, std::optional<double> temperature_C) {
  const auto& catalogue = lubricant::Catalogue::builtin();
  if (name.empty()) {
    if (temperature_C) throw InputError("--temperature-C: give an oil NAME to resolve");
    print_catalogue(catalogue);
    return exit_ok;
  }
  if (!temperature_C) throw InputError(fmt::format("--temperature-C: missing: give the temperature to resolve '{}' at", name));
  // The same path as a case's {"lubricant": {"name": ...}}, gear form: every property.
  const auto resolved = lubricant::resolve_section(
      json{{"name", name}}, "oil", lubricant::SectionForm::gear,
      lubricant::CaseTemperature{"--temperature-C", *temperature_C + lubricant::celsius_zero});
  std::cout << resolved.echo.dump(2) << "\n";
  return exit_ok;
}

}  // namespace gearbench::app
