#include "run_status.h"

namespace gearbench::dynamics {

const char* status_name(RunStatus status) { return status == RunStatus::periodic ? "periodic" : "not_periodic"; }

RunVerdict run_status(double periodicity) {
  if (periodicity <= max_periodicity)
    return {RunStatus::periodic, fmt::format("periodic: successive periods differ by {:.2g} of the peak-to-peak "
                                             "transmission error (at most {:.0e})",
                                             periodicity, max_periodicity)};
  return {RunStatus::not_periodic,
          fmt::format("not periodic: successive periods differ by {:.2g} of the peak-to-peak transmission error (more "
                      "than {:.0e}), so the dynamic factor is that of a transient; raise runup_cycles",
                      periodicity, max_periodicity)};
}

}  // namespace gearbench::dynamics
