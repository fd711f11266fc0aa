# Build provenance for reports and benchmark records.
# Dependency versions and compiler settings are fixed at configure time (build_info.cpp);
# the git sha and dirty flag are refreshed at every build (git_info.cpp), so a report
# always names the commit it was built from.

set(GEARBENCH_DEP_VERSIONS
  "Eigen=${Eigen3_VERSION};GSL=${GSL_VERSION};SUNDIALS=${SUNDIALS_VERSION};deal.II=${DEAL_II_PACKAGE_VERSION};GTest=${GTest_VERSION};benchmark=${benchmark_VERSION};nlohmann_json=${nlohmann_json_VERSION};CLI11=${CLI11_VERSION};fmt=${fmt_VERSION};FFTW=${FFTW3_VERSION}")
string(TOUPPER "${CMAKE_BUILD_TYPE}" _bt)
set(GEARBENCH_CXX_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_bt}}")
string(STRIP "${GEARBENCH_CXX_FLAGS}" GEARBENCH_CXX_FLAGS)
if(GEARBENCH_SANITIZE)
  string(APPEND GEARBENCH_CXX_FLAGS " -fsanitize=address,undefined")
endif()

configure_file(${CMAKE_CURRENT_LIST_DIR}/build_info.cpp.in
               ${CMAKE_BINARY_DIR}/generated/build_info.cpp @ONLY)

add_custom_target(gearbench_git_info
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
          -DOUTPUT=${CMAKE_BINARY_DIR}/generated/git_info.cpp
          -P ${CMAKE_CURRENT_LIST_DIR}/GitInfo.cmake
  BYPRODUCTS ${CMAKE_BINARY_DIR}/generated/git_info.cpp
  COMMENT "Recording git sha"
  VERBATIM)

add_library(gearbench_build_info STATIC
  ${CMAKE_BINARY_DIR}/generated/build_info.cpp
  ${CMAKE_BINARY_DIR}/generated/git_info.cpp)
add_dependencies(gearbench_build_info gearbench_git_info)
target_include_directories(gearbench_build_info PUBLIC ${CMAKE_CURRENT_LIST_DIR}/../reports)
