#pragma once
// The shell elements (Belytschko-Lin-Tsay quad, C0 DSG3 triangle), in one include: part and state,
// internal forces, lumped mass, time step and stress output. See docs/element-and-material.md.
#include "element/shell_forces.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_material_axes.hpp"
#include "element/shell_output.hpp"
#include "element/shell_part.hpp"
#include "element/shell_triangle.hpp"
