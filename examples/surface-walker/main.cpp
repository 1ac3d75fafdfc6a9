// Modules that walk over the surface of the ensemble at random, all at once: every module on
// layer `layer` or above is a walker. At each step a walker lists the motions it can make now,
// keeps those that need no helper, and takes one at random. A refused motion (a cell another
// walker has reserved, a pivot busy turning another, a queued request judged again too late) is
// not an error: the walker waits a random while and chooses again.
//
//   surface-walker run scene.json --program surface-walker --param layer=1 \
//       --param steps=30 --trace walk.jsonl --out walk.json
#include <datomsim/datomsim.h>

#include <memory>
#include <string>
#include <vector>

class SurfaceWalker : public datomsim::Program {
 public:
  explicit SurfaceWalker(const datomsim::Parameters& parameters)
      : layer_(int(parameters.integer("layer"))),
        steps_(int(parameters.integer("steps"))),
        patience_(int(parameters.integer("patience"))) {}

  void onStart(datomsim::Context& context) override {
    if (context.cell().z < layer_) return;
    walks_ = true;
    context.setColor({64, 220, 64});
    context.setTimer(0, kStep);
  }

  void onTimer(datomsim::Context& context, int) override { step(context); }

  void onMotionEnded(datomsim::Context& context, const datomsim::MotionEnded& ended) override {
    if (!ended.arrived) return refused(context, ended.refusal->text);
    ++done_;
    failures_ = 0;
    context.log("step " + std::to_string(done_) + " to " + datomsim::toString(ended.cell));
    if (done_ < steps_) context.setTimer(100 * datomsim::kMillisecond, kStep);
  }

  void report(datomsim::Report& report) const override {
    if (!walks_) return;
    report.set("steps", done_);
    report.set("refusals", refusals_);
    report.set("gave_up", gaveUp_);
  }

  static datomsim::ProgramEntry entry() {
    datomsim::ProgramEntry entry;
    entry.name = "surface-walker";
    entry.summary = "modules on --param layer=L and above walk at random over the surface";
    entry.parameters = {
        datomsim::Parameter::integer("layer", "the lowest layer whose modules walk", "1")
            .range(0, 1000000),
        datomsim::Parameter::integer("steps", "motions to make", "20").range(1, 100000),
        datomsim::Parameter::integer("patience", "refusals in a row before it gives up", "20")
            .range(1, 1000)};
    entry.make = [](datomsim::ModuleId, const datomsim::Parameters& parameters) {
      return std::make_unique<SurfaceWalker>(parameters);
    };
    return entry;
  }

 private:
  static constexpr int kStep = 1;

  void step(datomsim::Context& context) {
    std::vector<datomsim::Motion> free;
    for (datomsim::Motion& motion : context.motions()) {
      if (motion.helpers.empty()) free.push_back(std::move(motion));
    }
    if (free.empty()) return refused(context, "no motion without helpers from here");
    const datomsim::Motion& chosen = free[context.random().below(free.size())];
    const datomsim::MoveResult result = context.move(chosen);
    if (!result.ok()) refused(context, result.error());
  }

  void refused(datomsim::Context& context, const std::string& why) {
    ++refusals_;
    context.log("refused: " + why);
    if (++failures_ >= patience_) {
      context.log("gives up after " + std::to_string(failures_) + " refusals in a row");
      gaveUp_ = true;
      context.setColor({200, 200, 200});
      return;
    }
    const auto wait = context.random().between(200, 1200) * datomsim::kMillisecond;
    context.setTimer(wait, kStep);
  }

  int layer_;
  int steps_;
  int patience_;
  bool walks_ = false;
  int done_ = 0;
  int refusals_ = 0;
  int failures_ = 0;  // in a row
  bool gaveUp_ = false;
};

int main(int argc, char** argv) {
  return datomsim::main(argc, argv, {SurfaceWalker::entry()});
}
