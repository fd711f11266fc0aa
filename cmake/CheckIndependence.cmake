# The layering of the tree, checked on every #include (issue 21): each folder names what it may
# not include, so that a reference never shares code with the solver it checks, and the
# product (solvers/) and the report writer never reach into references, the CLI or the checks.
#   reference/                  -> solvers/model only
#   solvers/                    -> no reference/, app/ or verification/ code
#   reports/                    -> solvers/model only; no reference/ code
#   verification/checks/        -> no app/ code (the checks run inside `gearbench verify`)
# Headers are recognised by the folder they are included through ("ehl/…", "closed_form/…")
# or, for app/ and verification/, by their names.
set(solver_folders "geometry|ehl|stiffness|efficiency|dynamics|lubricant|micropitting")
set(reference_folders "closed_form|quadrature|ode|ehl_newton|construction|fe_tooth")
set(app_headers "kind_registry\\.h|commands\\.h|kinds/|bench_support\\.h|lubricant_resolution\\.h|mpi_session\\.h|interrupt\\.h|sweep_command\\.h")
set(verification_headers "checks/|check_registry\\.h|support/|outcome\\.h")

set(rules
  "reference|\"(${solver_folders})/|reference/ uses solver code"
  "solvers|\"(${reference_folders})/|solvers/ uses reference code"
  "solvers|\"(${app_headers})|solvers/ uses app code"
  "solvers|\"(${verification_headers})|solvers/ uses verification code"
  "reports|\"(${solver_folders})/|reports/ uses solver code"
  "reports|\"(${reference_folders})/|reports/ uses reference code"
  "verification/checks|\"(${app_headers})|verification/checks uses app code")

set(bad "")
foreach(rule IN LISTS rules)
  string(REPLACE "|" ";" parts "${rule}")
  # The pattern itself holds "|": the folder is the first field, the message the last.
  list(GET parts 0 folder)
  list(GET parts -1 message)
  string(REGEX REPLACE "^[^|]*\\|(.*)\\|[^|]*$" "\\1" pattern "${rule}")
  file(GLOB_RECURSE files ${ROOT}/${folder}/*.h ${ROOT}/${folder}/*.cpp)
  foreach(f IN LISTS files)
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include")
    foreach(l IN LISTS lines)
      if(l MATCHES "${pattern}")
        list(APPEND bad "${message}: ${f}: ${l}")
      endif()
    endforeach()
  endforeach()
endforeach()
if(bad)
  string(REPLACE ";" "\n" bad "${bad}")
  message(FATAL_ERROR "layering violated:\n${bad}")
endif()
message(STATUS "layering: reference, solvers, reports and verification/checks include only what they may: ok")
