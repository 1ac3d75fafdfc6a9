#include "mechanics/load_solver.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include <fmt/format.h>

#include "geometry/lattice.h"

namespace datomsim::mechanics {

namespace {

// Column-major with 32-bit indices: a million modules make a quarter of a billion entries.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

constexpr int kDofs = 6;  // per node: 3 translations, then 3 rotations
constexpr int32_t kHeld = -1;

// The world's unit vector of each of the 12 directions: every beam lies along one of them.
std::array<geometry::Vec3, geometry::kDirectionCount> directionAxes() {
  std::array<geometry::Vec3, geometry::kDirectionCount> axes;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    axes[d] = geometry::normalized(geometry::worldOffset(geometry::neighbourOffset(d), 1.0));
  }
  return axes;
}

// The beams' stiffness by direction: all beams are alike but for their axis.
std::array<elastic::BeamMatrix, geometry::kDirectionCount> stiffnessByDirection(
    const LoadModel& model) {
  const auto axes = directionAxes();
  std::array<elastic::BeamMatrix, geometry::kDirectionCount> matrices;
  for (int d = 0; d < geometry::kDirectionCount; ++d) {
    matrices[d] = elastic::beamStiffness(model.section, model.parameters.youngModulus, axes[d]);
  }
  return matrices;
}

struct Assembly {
  SparseMatrix stiffness;  // lower triangle
  Eigen::VectorXd load;
  // The first unknown of each node, kHeld for a supported one (its motion is zero).
  std::vector<int32_t> firstDof;
};

// K's lower triangle column by column, each column's rows in increasing order, so that every
// entry is appended to room reserved for it: the diagonal block of the node, then the blocks of
// its free neighbours numbered after it.
Assembly assemble(const LoadModel& model, const std::array<elastic::BeamMatrix, 12>& stiffness) {
  Assembly out;
  const size_t count = model.nodes.size();
  out.firstDof.assign(count, kHeld);
  int32_t unknowns = 0;
  for (size_t i = 0; i < count; ++i) {
    if (!model.nodes[i].supported) {
      out.firstDof[i] = unknowns;
      unknowns += kDofs;
    }
  }
  // Everything on the ground: nothing to solve (and Eigen's compression of an empty reserved
  // matrix reads out of bounds).
  if (unknowns == 0) return out;
  const Incidence incidence = incidenceOf(model);
  auto otherEnd = [&](const Beam& beam, uint32_t node) { return beam.a == node ? beam.b : beam.a; };
  // Entries per column.
  Eigen::VectorXi perColumn(unknowns);
  for (uint32_t n = 0; n < count; ++n) {
    if (out.firstDof[n] == kHeld) continue;
    int later = 0;
    for (uint32_t k = incidence.start[n]; k < incidence.start[n + 1]; ++k) {
      const uint32_t other = otherEnd(model.beams[incidence.beams[k]], n);
      if (out.firstDof[other] > out.firstDof[n]) ++later;
    }
    for (int c = 0; c < kDofs; ++c) perColumn[out.firstDof[n] + c] = kDofs - c + kDofs * later;
  }
  out.stiffness.resize(unknowns, unknowns);
  out.stiffness.reserve(perColumn);
  // The weight of each free module at its centre.
  const geometry::Vec3 weight = model.parameters.gravity * model.moduleMass;
  out.load = Eigen::VectorXd::Zero(unknowns);
  std::vector<std::pair<int32_t, uint32_t>> later;  // (first unknown, beam) of later neighbours
  for (uint32_t n = 0; n < count; ++n) {
    const int32_t first = out.firstDof[n];
    if (first == kHeld) continue;
    out.load.segment<3>(first) = Eigen::Vector3d(weight.x, weight.y, weight.z);
    Eigen::Matrix<double, kDofs, kDofs> diagonal = Eigen::Matrix<double, kDofs, kDofs>::Zero();
    later.clear();
    for (uint32_t k = incidence.start[n]; k < incidence.start[n + 1]; ++k) {
      const Beam& beam = model.beams[incidence.beams[k]];
      const int at = beam.a == n ? 0 : kDofs;
      diagonal += stiffness[beam.direction].block<kDofs, kDofs>(at, at);
      const int32_t otherFirst = out.firstDof[otherEnd(beam, n)];
      if (otherFirst > first) later.emplace_back(otherFirst, incidence.beams[k]);
    }
    std::sort(later.begin(), later.end());
    for (int c = 0; c < kDofs; ++c) {
      for (int r = c; r < kDofs; ++r) out.stiffness.insert(first + r, first + c) = diagonal(r, c);
      for (const auto& [otherFirst, beamIndex] : later) {
        const Beam& beam = model.beams[beamIndex];
        // Rows of the other end, columns of this one.
        const int rows = beam.a == n ? kDofs : 0;
        const int columns = kDofs - rows;
        for (int r = 0; r < kDofs; ++r) {
          out.stiffness.insert(otherFirst + r, first + c) =
              stiffness[beam.direction](rows + r, columns + c);
        }
      }
    }
  }
  out.stiffness.makeCompressed();
  return out;
}

size_t matrixBytes(const SparseMatrix& matrix) {
  return size_t(matrix.nonZeros()) * (sizeof(double) + sizeof(int)) +
         size_t(matrix.outerSize() + 1) * sizeof(int);
}

}  // namespace

namespace {

// Each node's motion, zero at the supports, and each latch's load from its ends' motions.
void readSolution(const LoadModel& model, const Assembly& assembly,
                  const std::array<elastic::BeamMatrix, geometry::kDirectionCount>& stiffness,
                  const Eigen::VectorXd& u, LoadSolution& solution) {
  const size_t count = model.nodes.size();
  solution.displacement.assign(count, {});
  solution.rotation.assign(count, {});
  for (size_t i = 0; i < count; ++i) {
    const int32_t first = assembly.firstDof[i];
    if (first == kHeld) continue;
    solution.displacement[i] = {u[first], u[first + 1], u[first + 2]};
    solution.rotation[i] = {u[first + 3], u[first + 4], u[first + 5]};
  }
  const auto axes = directionAxes();
  solution.latches.reserve(model.beams.size());
  for (const Beam& beam : model.beams) {
    elastic::BeamVector ends = elastic::BeamVector::Zero();
    for (const auto& [node, at] : {std::pair{beam.a, 0}, std::pair{beam.b, kDofs}}) {
      const int32_t first = assembly.firstDof[node];
      if (first != kHeld) ends.segment<kDofs>(at) = u.segment<kDofs>(first);
    }
    solution.latches.push_back(elastic::latchLoad(stiffness[beam.direction], ends,
                                                  axes[beam.direction], model.section.length,
                                                  model.parameters));
  }
}

// The weights plus a case's loads at the free nodes (a load on a supported node goes to the
// ground).
Eigen::VectorXd loadOfCase(const Assembly& assembly, std::span<const NodeLoad> extra) {
  Eigen::VectorXd load = assembly.load;
  for (const NodeLoad& added : extra) {
    const int32_t first = assembly.firstDof[added.node];
    if (first == kHeld) continue;
    load.segment<3>(first) += Eigen::Vector3d(added.force.x, added.force.y, added.force.z);
    load.segment<3>(first + 3) += Eigen::Vector3d(added.moment.x, added.moment.y, added.moment.z);
  }
  return load;
}

}  // namespace

Result<std::vector<LoadSolution>> solveLoadCases(const LoadModel& model,
                                                 std::span<const std::vector<NodeLoad>> cases,
                                                 const SolverOptions& options) {
  const auto stiffness = stiffnessByDirection(model);
  const Assembly assembly = assemble(model, stiffness);
  const Eigen::Index unknowns = assembly.load.size();
  const size_t freeNodes = size_t(unknowns / kDofs);
  const bool direct = options.method == SolverMethod::kDirect ||
                      (options.method == SolverMethod::kAutomatic && freeNodes <= kDirectLimit);
  // One factorisation (or one preconditioner) for every case.
  std::optional<Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>> factor;
  std::optional<
      Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower, Eigen::DiagonalPreconditioner<double>>>
      iterative;
  size_t memoryBytes = 0;
  if (unknowns > 0 && direct) {
    // Sparse LDL^T with a fill-reducing ordering (AMD): exact to rounding.
    factor.emplace(assembly.stiffness);
    if (factor->info() != Eigen::Success) {
      return Error{"the stiffness matrix cannot be factorised: the model is not held still"};
    }
    memoryBytes = 2 * matrixBytes(assembly.stiffness) +
                  size_t(factor->matrixL().nestedExpression().nonZeros()) * 12;
  } else if (unknowns > 0) {
    // Conjugate gradients: only K and a few vectors are held.
    iterative.emplace();
    iterative->setTolerance(options.tolerance);
    iterative->setMaxIterations(options.maxIterations > 0 ? options.maxIterations : int(unknowns));
    iterative->compute(assembly.stiffness);
    memoryBytes = matrixBytes(assembly.stiffness) + 8 * sizeof(double) * size_t(unknowns);
  }
  std::vector<LoadSolution> solutions;
  solutions.reserve(cases.size());
  for (const std::vector<NodeLoad>& extra : cases) {
    LoadSolution solution;
    solution.memoryBytes = memoryBytes;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(unknowns);
    if (unknowns == 0) {
      solution.method = "none (every module is on the ground)";
    } else {
      const Eigen::VectorXd load = loadOfCase(assembly, extra);
      if (factor) {
        u = factor->solve(load);
        solution.method = "sparse LDLT";
      } else {
        u = iterative->solve(load);
        solution.iterations = int(iterative->iterations());
        if (iterative->info() != Eigen::Success) {
          return Error{fmt::format(
              "the conjugate gradient did not converge in {} iterations (relative residual "
              "{:.3g})",
              iterative->iterations(), iterative->error())};
        }
        solution.method = "conjugate gradient";
      }
      const double loadNorm = load.norm();
      const Eigen::VectorXd residual =
          assembly.stiffness.selfadjointView<Eigen::Lower>() * u - load;
      solution.residual = loadNorm > 0 ? residual.norm() / loadNorm : residual.norm();
    }
    readSolution(model, assembly, stiffness, u, solution);
    solution.totalWeight =
        double(model.nodes.size()) * model.moduleMass * geometry::norm(model.parameters.gravity);
    solutions.push_back(std::move(solution));
  }
  return solutions;
}

Result<LoadSolution> solveLoads(const LoadModel& model, const SolverOptions& options) {
  const std::vector<NodeLoad> none;
  auto solved = solveLoadCases(model, std::span(&none, 1), options);
  if (!solved) return Error{solved.error()};
  return std::move(solved->front());
}

std::vector<double> worstSafetyByNode(const LoadModel& model, const LoadSolution& solution) {
  std::vector<double> worst(model.nodes.size(), std::numeric_limits<double>::infinity());
  for (size_t k = 0; k < model.beams.size(); ++k) {
    const double safety = solution.latches[k].safety;
    worst[model.beams[k].a] = std::min(worst[model.beams[k].a], safety);
    worst[model.beams[k].b] = std::min(worst[model.beams[k].b], safety);
  }
  return worst;
}

}  // namespace datomsim::mechanics
