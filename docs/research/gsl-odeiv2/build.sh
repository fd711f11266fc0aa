#!/bin/sh
# Links the lead's already-built static libraries (Release, -O3); this file at -O2.
B=/work/main/build/default
c++ -std=c++20 -O2 -DNDEBUG -DFMT_SHARED -I/work/main/verification -I/work/main/solvers -I/work/main/reference \
  -isystem /usr/include/eigen3 -o /tmp/gslode/gslode /tmp/gslode/gslode.cpp \
  $B/solvers/libgearbench_solvers.a $B/reference/libgearbench_reference.a $B/solvers/libgearbench_model.a \
  -lsundials_cvode -lsundials_arkode -lsundials_nvecserial -lfftw3 -lgsl -lgslcblas -lfmt -ldl
