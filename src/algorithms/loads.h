// The distributed load solver (docs/mechanics.md, "The distributed solver"): the modules solve the
// load model's equations K u = f together, each holding its own six unknowns and its own rows of
// K, talking only through latched connectors. Written against the public API
// (datomsim/program.h), as a researcher's program would be.
//
// The model is mechanics' (one node per module, one beam per latch, the ground layer held; the
// same beam element and parameters, elastic/), the iteration the conjugate gradient method with a
// block Jacobi preconditioner: each module inverts its own 6 x 6 diagonal block, the products K p
// are exchanges of 6-vectors between latched neighbours, and the two dot products of an iteration
// are sums up a spanning tree from the root (a convergecast) whose result the root sends back
// down (a broadcast). The tree is built first by the echo algorithm, which also sums the first
// residual. At the end every module computes the loads of its own latches as mechanics::solveLoads
// does (elastic::latchLoad) and reports the worst of them.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datomsim/program.h"
#include "elastic/beam_element.h"

namespace datomsim::algorithms {

class LoadsProgram final : public Program {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  // What every module is told: the load model's parameters and the iteration's.
  struct Settings {
    elastic::LoadParameters parameters;
    // The iteration stops once |K u - f| <= tolerance |f|.
    double tolerance = 1e-10;
    int64_t maxIterations = 10'000;
    Cell root;
  };

  // The echo algorithm builds the tree: a module joins by the first explore it hears (its sender
  // is its parent) and explores every other latched connector; once it has heard from every one
  // it echoes to its parent the sums of its subtree: the first residual's r.z and r.r, the
  // modules, the modules on the ground.
  struct ExploreMsg {
    static constexpr std::string_view kName = "LoadExploreMsg";
  };
  struct EchoMsg {
    static constexpr std::string_view kName = "LoadEchoMsg";
    double rz;
    double rr;
    uint32_t modules;
    uint32_t held;
  };
  // Broadcast by the root: the next search direction is p = z + beta p.
  struct StepMsg {
    static constexpr std::string_view kName = "LoadStepMsg";
    double beta;
  };
  // A module's share of the search direction, to its free latched neighbours.
  struct DirectionMsg {
    static constexpr std::string_view kName = "LoadDirectionMsg";
    double p[6];
  };
  // Convergecast: the subtree's sum of p.Kp.
  struct CurvatureMsg {
    static constexpr std::string_view kName = "LoadCurvatureMsg";
    double pq;
  };
  // Broadcast by the root: the step length along p.
  struct AlphaMsg {
    static constexpr std::string_view kName = "LoadAlphaMsg";
    double alpha;
  };
  // Convergecast: the subtree's sums of r.z and r.r of the new residual.
  struct ResidualMsg {
    static constexpr std::string_view kName = "LoadResidualMsg";
    double rz;
    double rr;
  };
  // Broadcast by the root: the iteration is over.
  struct DoneMsg {
    static constexpr std::string_view kName = "LoadDoneMsg";
    double residual;
    int32_t iterations;
    bool converged;
  };
  // A free module's displacement and rotation, to every latched neighbour, once it is done.
  struct DisplacementMsg {
    static constexpr std::string_view kName = "LoadDisplacementMsg";
    double u[6];
  };

  // "loads", its parameters: the load model's (as `datomsim loads` names them), the tolerance,
  // the largest number of iterations and the root.
  static ProgramEntry entry();

  // Every module is told the same settings, each its own copy.
  explicit LoadsProgram(const Settings& settings) : settings_(settings) {}

  void onStart(Context& context) override;
  void onMessage(Context& context, int connector, const Message& message) override;
  // Every module: "safety" (the smallest safety factor of its latches, when one carries
  // something), "force" and "moment" (the largest of its latches, N and N m). The root also:
  // "iterations", "residual" (|K u - f| / |f| as the iteration measured it), "converged" and
  // "modules" (how many the tree reached: the modules that took part).
  void report(Report& report) const override;
  // Whether the tree has reached it, the iteration under way (the root counts them), or done.
  std::string describe() const override;

 private:
  // One of the module's latched connections, as it knows it.
  struct Latch {
    int connector = 0;
    int direction = 0;  // world direction from this module to the neighbour
    bool neighbourHeld = false;
    Matrix6 coupling;  // K's block of this module's rows and the neighbour's columns
    Vector6 theirs;    // the neighbour's last search direction, then its displacement
  };
  // Each latch's load once the module is done, by the module's own connectors (what this module
  // passes to the neighbour: elastic::latchLoad with this module as end a).
  struct LatchResult {
    int connector = 0;
    elastic::LatchLoad load;
  };

  void prepare(Context& context);
  // The tree.
  void explore(Context& context, int from);
  void heard(Context& context);
  void broadcast(Context& context, const Message& message);
  // The reductions: this module's share, a child's, and the whole at the root.
  void contribute(Context& context, double first, double second);
  void childSum(Context& context, double first, double second);
  void reduced(Context& context);
  // The iteration's steps, as the broadcasts reach the module.
  void step(Context& context, double beta);
  void multiply(Context& context);
  void advance(Context& context, double alpha);
  void finish(Context& context, const DoneMsg& done);
  void rootDecides(Context& context);
  void computeLoads(Context& context);
  bool isRoot(Context& context) const { return context.cell() == settings_.root; }

  Settings settings_;
  bool prepared_ = false;
  bool held_ = false;
  std::vector<Latch> latches_;
  int freeNeighbours_ = 0;
  Matrix6 diagonal_ = Matrix6::Zero();
  Matrix6 preconditioner_ = Matrix6::Zero();  // the diagonal block's inverse
  Vector6 f_ = Vector6::Zero(), x_ = Vector6::Zero(), r_ = Vector6::Zero(), z_ = Vector6::Zero(),
          p_ = Vector6::Zero(), q_ = Vector6::Zero();

  // The tree: the parent's connector (-1 at the root), the children's connectors.
  bool joined_ = false;
  int parent_ = -1;
  uint16_t children_ = 0;
  int childCount_ = 0;
  int heard_ = 0;
  EchoMsg subtree_{};

  // The reduction under way: this module's share given, children heard, the sums so far.
  bool ownGiven_ = false;
  int childrenHeard_ = 0;
  double sum_[2] = {0, 0};
  // Which reduction the root is waiting for.
  enum class Awaiting : uint8_t { kTree, kCurvature, kResidual };
  Awaiting awaiting_ = Awaiting::kTree;

  // The product K p: this module's p is ready, and how many neighbours' have come.
  bool directionReady_ = false;
  int directions_ = 0;

  // The root's iteration: r.z, r.r and |f|^2, the iterations so far.
  double rz_ = 0;
  double rr_ = 0;
  double ff_ = 0;
  int32_t iterations_ = 0;

  // The end.
  std::optional<DoneMsg> done_;
  int displacements_ = 0;
  bool finished_ = false;
  std::vector<LatchResult> results_;
};

}  // namespace datomsim::algorithms
