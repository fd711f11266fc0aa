# Fails when the gearbench executable loads deal.II's stack or MPI at start-up (issue 27):
# every shared library it loads is paid for by every run, `--version` included; both are
# plugins loaded when needed. Reads `ldd`, so a library pulled in indirectly counts too. The
# FE plugin, which loads all of them (deal.II links MPI), is read the same way and must match,
# so that the patterns are known to find what they name.
# Usage: cmake -DEXE=gearbench -DPLUGIN=libgearbench_fe_backend.so -P CheckLinks.cmake
set(heavy "libdeal[._]ii" "libpetsc" "libslepc" "libtrilinos" "epetra" "libgmsh" "libTKernel" "libmpi")

function(loaded_libraries file out)
  execute_process(COMMAND ldd ${file} OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "ldd ${file} failed (${rc})")
  endif()
  string(REGEX MATCHALL "[^\n]+" lines "${text}")
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

loaded_libraries(${EXE} exe_libs)
loaded_libraries(${PLUGIN} plugin_libs)
list(LENGTH exe_libs count)
set(bad "")
foreach(pattern IN LISTS heavy)
  set(in_plugin FALSE)
  foreach(l IN LISTS plugin_libs)
    if(l MATCHES "${pattern}")
      set(in_plugin TRUE)
    endif()
  endforeach()
  if(NOT in_plugin)
    message(FATAL_ERROR "the pattern ${pattern} finds nothing in the FE plugin's libraries: fix the pattern")
  endif()
  foreach(l IN LISTS exe_libs)
    if(l MATCHES "${pattern}")
      list(APPEND bad "${l}")
    endif()
  endforeach()
endforeach()
if(bad)
  string(REPLACE ";" "\n" bad "${bad}")
  message(FATAL_ERROR "${EXE} loads what only the plugins may:\n${bad}")
endif()
message(STATUS "${EXE}: ${count} shared libraries at start-up, none of deal.II's stack or MPI")
