// Every module learns its hop count from a root: the root knows 0 and tells its neighbours; a
// module that hears a smaller count than it knows keeps it and tells its other neighbours one
// more. (datomsim's built-in `flood` is the same program; this one is called my-flood.)
//
//   flood-example run scene.json --program my-flood --param root=0,0,0 --out hops.json
#include <datomsim/datomsim.h>

#include <memory>
#include <string>

struct HopsMsg {
  static constexpr std::string_view kName = "HopsMsg";
  int hops;
};

class Flood : public datomsim::Program {
 public:
  explicit Flood(datomsim::Cell root) : root_(root) {}

  void onStart(datomsim::Context& context) override {
    if (context.cell() == root_) learn(context, 0, -1);
  }

  void onMessage(datomsim::Context& context, int connector,
                 const datomsim::Message& message) override {
    const HopsMsg* told = message.as<HopsMsg>();
    if (told && (hops_ < 0 || told->hops < hops_)) learn(context, told->hops, connector);
  }

  void report(datomsim::Report& report) const override {
    if (hops_ >= 0) report.set("hops", hops_);
  }

  // What a live front end shows of this module during a run.
  std::string describe() const override {
    return hops_ < 0 ? "not reached yet" : "hops from the source: " + std::to_string(hops_);
  }

  static datomsim::ProgramEntry entry() {
    datomsim::ProgramEntry entry;
    entry.name = "my-flood";
    entry.summary = "every module learns its hop count from the root";
    entry.parameters = {datomsim::Parameter::cell("root", "where the flood starts").module()};
    entry.make = [](datomsim::ModuleId, const datomsim::Parameters& parameters) {
      return std::make_unique<Flood>(parameters.cell("root"));
    };
    return entry;
  }

 private:
  void learn(datomsim::Context& context, int hops, int from) {
    hops_ = hops;
    context.sendToAll(datomsim::Message::of(HopsMsg{hops + 1}), from);
  }

  datomsim::Cell root_;
  int hops_ = -1;
};

int main(int argc, char** argv) {
  return datomsim::main(argc, argv, {Flood::entry()});
}
