#pragma once
// GSL's failures as status codes turned into errors, never as GSL's default handler, which
// prints and calls abort() and so takes the whole process (a `verify` run, a sweep) with it.
// One place for solvers/ and reference/ alike (issue 21): every function that calls GSL
// first calls gsl_use_status_codes(), then passes each returned status to gsl_check().
#include <string_view>

namespace gearbench::model {

/// Switches GSL's default error handler off, once per process (cheap after the first call).
void gsl_use_status_codes();

/// Throws std::runtime_error("GSL <call>: <GSL's message>").
[[noreturn]] void gsl_fail(int status, std::string_view call);

/// gsl_fail for any status but GSL_SUCCESS (0); inline, for calls on hot paths.
inline void gsl_check(int status, std::string_view call) {
  if (status != 0) gsl_fail(status, call);
}

}  // namespace gearbench::model
