#include <iostream>

#include "commands.h"
#include "compare.h"

namespace gearbench::app {

int report_compare_command(const std::string& before, const std::string& after) {
  const auto comparison = reports::compare_reports(reports::load_report(before),
                                                   reports::load_report(after));
  std::cout << comparison.text();
  return comparison.regressions.empty() ? exit_ok : exit_failed;
}

}  // namespace gearbench::app
