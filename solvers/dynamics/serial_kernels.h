#pragma once
// Compiled serial N_Vector kernels for the integrators' hot vector operations.
//
// Measured (docs/dynamics-model.md, "Integrators: work–precision"): Debian 12's SUNDIALS
// 6.4.1 libraries carry unoptimised vector kernels (every loop index kept on the stack), and
// with 15 or 28 unknowns N_VLinearCombination alone took 40 % of a Dormand–Prince run.
// SUNDIALS dispatches every vector operation through the vector's ops table (struct
// _generic_N_Vector_Ops, copied by N_VClone), so the integrators install these
// same-semantics kernels on their template vector before the package clones it.
#include <nvector/nvector_serial.h>

namespace gearbench::dynamics {

/// Replaces the hot operations of the serial vector `v` (and of its future clones).
void install_serial_kernels(N_Vector v);

}  // namespace gearbench::dynamics
