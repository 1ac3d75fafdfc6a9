// Solving a load model (load_model.h): the stiffness equations K u = f of the beams under the
// modules' weights, the supported nodes held, then each latch's load and safety factor.
//
// K is assembled once per solve as a sparse symmetric matrix (Eigen, its lower triangle only).
// Up to kDirectLimit free modules it is factorised (sparse LDL^T: exact to rounding); above, the
// conjugate gradient method with a diagonal (Jacobi) preconditioner solves it in a memory that
// grows as the number of latches, where a factor would fill in (docs/mechanics.md, "Solver").
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "datomsim/result.h"
#include "elastic/beam_element.h"
#include "geometry/vec3.h"
#include "mechanics/load_model.h"

namespace datomsim::mechanics {

// The most free (not supported) modules solved by factorisation when the method is automatic.
inline constexpr size_t kDirectLimit = 20'000;

enum class SolverMethod { kAutomatic, kDirect, kIterative };

struct SolverOptions {
  SolverMethod method = SolverMethod::kAutomatic;
  // The iterative solver stops once |K u - f| <= tolerance |f|.
  double tolerance = 1e-10;
  // The iterative solver's largest number of iterations; 0 for the number of unknowns.
  int maxIterations = 0;
};

struct LoadSolution {
  // Per node (model.nodes' order): displacement (m) and rotation (rad, an axis times an angle).
  std::vector<geometry::Vec3> displacement;
  std::vector<geometry::Vec3> rotation;
  // Per beam (model.beams' order).
  std::vector<elastic::LatchLoad> latches;
  double totalWeight = 0;  // N, every module's
  // How it was solved: "sparse LDLT" or "conjugate gradient", the iterations the latter took and
  // the relative residual |K u - f| / |f| it reached.
  std::string method;
  int iterations = 0;
  double residual = 0;
  // Bytes held by the matrix and the factor or the solver's vectors, at their largest.
  size_t memoryBytes = 0;
};

// Solves the model under the gravity of its parameters. Refuses a system the solver cannot
// solve (a factorisation that fails, an iteration that does not converge).
Result<LoadSolution> solveLoads(const LoadModel& model, const SolverOptions& options = {});

// A load at a node besides its weight: a force (N) and a moment (N m) at its centre.
struct NodeLoad {
  uint32_t node = 0;
  geometry::Vec3 force;
  geometry::Vec3 moment;
};

// Solves the model under its weights plus each case's loads, with one factorisation (or one
// preconditioner) for them all: a solution per case. Refuses as solveLoads does.
Result<std::vector<LoadSolution>> solveLoadCases(const LoadModel& model,
                                                 std::span<const std::vector<NodeLoad>> cases,
                                                 const SolverOptions& options = {});

// The smallest safety factor of the latches at each node (infinite for a node without latches).
std::vector<double> worstSafetyByNode(const LoadModel& model, const LoadSolution& solution);

}  // namespace datomsim::mechanics
