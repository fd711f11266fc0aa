#include "gsl_status.h"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <stdexcept>

namespace gearbench::model {

void gsl_use_status_codes() {
  [[maybe_unused]] static const bool switched_off = [] {
    gsl_set_error_handler_off();
    return true;
  }();
}

void gsl_fail(int status, std::string_view call) {
  throw std::runtime_error(fmt::format("GSL {}: {}", call, gsl_strerror(status)));
}

}  // namespace gearbench::model
