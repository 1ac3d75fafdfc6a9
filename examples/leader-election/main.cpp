// Leader election, minimum id wins, and a breadth-first spanning tree rooted at the leader.
//
// Every module starts as its own candidate and tells its neighbours (candidate, depth 0). A
// module that hears of a smaller candidate, or of its own candidate by a shorter way, takes it,
// takes the teller as its parent and tells its other neighbours. When the messages stop, every
// module knows the smallest id of its piece of the ensemble and its depth in the tree.
//
//   leader-election run scene.json --program leader-election --out leaders.json
#include <datomsim/datomsim.h>

#include <cstdint>
#include <memory>

struct CandidateMsg {
  static constexpr std::string_view kName = "CandidateMsg";
  uint32_t candidate;
  int depth;  // the teller's depth
};

class LeaderElection : public datomsim::Program {
 public:
  void onStart(datomsim::Context& context) override {
    candidate_ = context.id().value;
    depth_ = 0;
    context.setColor({230, 60, 60});
    context.sendToAll(datomsim::Message::of(CandidateMsg{candidate_, depth_}));
  }

  void onMessage(datomsim::Context& context, int connector,
                 const datomsim::Message& message) override {
    const CandidateMsg* told = message.as<CandidateMsg>();
    if (!told) return;
    const bool smaller = told->candidate < candidate_;
    const bool shorter = told->candidate == candidate_ && told->depth + 1 < depth_;
    if (!smaller && !shorter) return;
    candidate_ = told->candidate;
    depth_ = told->depth + 1;
    parent_ = connector;
    context.setColor({60, 120, 230});
    context.sendToAll(datomsim::Message::of(CandidateMsg{candidate_, depth_}), connector);
  }

  void report(datomsim::Report& report) const override {
    report.set("leader", candidate_);
    report.set("depth", depth_);
    report.set("parent_connector", parent_);
  }

  static datomsim::ProgramEntry entry() {
    datomsim::ProgramEntry entry;
    entry.name = "leader-election";
    entry.summary = "the smallest id leads; a breadth-first spanning tree grows from it";
    entry.make = [](datomsim::ModuleId, const datomsim::Parameters&) {
      return std::make_unique<LeaderElection>();
    };
    return entry;
  }

 private:
  uint32_t candidate_ = 0;
  int depth_ = 0;
  int parent_ = -1;  // the connector towards the leader; -1 for the leader
};

int main(int argc, char** argv) {
  return datomsim::main(argc, argv, {LeaderElection::entry()});
}
