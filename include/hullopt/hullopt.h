#pragma once
// hullopt's public C++ API, one include for the design chain of a high-speed hull in head seas:
//
//   hull::DesignVariables, hull::GenerateHull        parametric hull at a fixed displacement (parametric_hull/)
//   hull::HullForm, hull::MassProperties              a hull's stations and mass properties
//   hull::ComputeHydrostatics                         displacement, coefficients, centres, GM
//   sk::RaoSolverOptions, sk::ComputeRaos             heave and pitch RAOs by the time-domain strip method
//   sk::FrequencySpec, sk::WaveFrequencies            wave-frequency lists from λ/L, ω or ω_e
//   sk::SeaState, sk::EvaluateDesign                  rms vertical accelerations and MSI in head seas
//
// SI units throughout; axes and phases as in docs/conventions.md. Options structs have
// `bool IsValid(std::string* error) const`; bad requests throw std::invalid_argument (bad options) or
// std::domain_error (a request that cannot be met), each with a one-line message naming the rule.
// Link the CMake target hullopt::hullopt (find_package(hullopt)).
#include "hullopt/version.h"
#include "parametric_hull/design_variables.h"
#include "parametric_hull/hull_form.h"
#include "parametric_hull/hull_generator.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/rao_table.h"
#include "seas/design_evaluation.h"
#include "seas/passenger_positions.h"
#include "seas/wave_spectrum.h"
