// Messages for a module that is not a neighbour, carried hop by hop between latched neighbours.
//
// Requests of Algorithm 1 go from the mobile to its helpers, up to two cells away (helpers.h). Each
// hop forwards the message through the latched connector whose neighbour is nearest to the
// target cell, if nearer than itself (greedy geographic routing). Where no neighbour is nearer
// (typically: a helper has just retracted the connector that faced the mobile), it
// floods to its latched neighbours, each module forwarding a given message once, within a hop
// limit and within a ball around the target one cell wider than where greedy stalled: the detour
// is local, and a flood that roamed the whole ensemble would cost a message per latch. A message
// marked kAroundAPiston (a helper's answer on the paper's terms, one motion at a time) floods in a
// ball two cells wider: the way round the helper's own compressed piston goes through its
// remaining neighbours, up to a cell farther from the target than the helper, and theirs, up to
// one more.
// Delivery happens at the module in the target cell; a flood can bring it several copies, of
// which the target handles the first (Router::firstCopy).
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "datomsim/program.h"
#include "geometry/cell.h"

namespace datomsim::algorithms {

struct RoutedMsg {
  geometry::Cell target;
  geometry::Cell origin;  // where the answer goes
  uint32_t request = 0;   // the origin's request number
  int8_t axis = -1;       // a world piston axis, for a helper's DeformMsg
  int8_t hopsLeft = 0;    // for flooding; kGreedyOnly: dropped where greedy routing stalls
  // While flooding, the farthest a copy may be from the target (squaredDistance4); 0: greedy.
  // 16 bits keep the routed messages with the most payload within a message's capacity.
  uint16_t floodBound = 0;

  bool flooding() const { return floodBound > 0; }
};

// A routed message that never floods: cheap, for information that may be lost (a distance some
// other module will also tell).
inline constexpr int8_t kGreedyOnly = -1;
// A routed message whose flood, where greedy routing stalls, keeps within a ball two cells wider
// than where it stalled, not one: a helper's answer that must go round its own compressed piston.
inline constexpr int8_t kAroundAPiston = -2;

class Router {
 public:
  static constexpr int8_t kFloodHops = 8;

  // Sends towards routed.target from this module, choosing the next hop. Hops go through
  // connectors latched at the time, so a refusal is a bug of the caller's world: the first one is
  // returned.
  template <typename T>
  Status send(Context& context, T routed, int arrivedThrough = -1) {
    return forward(context, routed, kindOf<T>(), arrivedThrough,
                   [&](int connector, const RoutedMsg& next) {
                     T copy = routed;
                     static_cast<RoutedMsg&>(copy) = next;
                     return context.send(connector, Message::of(copy));
                   });
  }

  // At the target: whether this copy is the first to arrive, the one to handle. A flood reaches
  // the target through each of its latched neighbours in the ball; a greedy message arrives once.
  template <typename T>
  bool firstCopy(const T& routed) {
    return !routed.flooding() || !seen(routed, kindOf<T>());
  }

 private:
  // A number per message type, so that a DeformMsg and an AckDeform with the same cells and
  // request number are told apart.
  template <typename T>
  static constexpr uint64_t kindOf() {
    uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a
    for (const char c : T::kName) hash = (hash ^ uint8_t(c)) * 0x100000001b3ULL;
    return hash;
  }

  template <typename Send>
  Status forward(Context& context, const RoutedMsg& routed, uint64_t kind, int arrivedThrough,
                 Send&& sendThrough);

  // Whether this module met the message before; remembers it if not.
  bool seen(const RoutedMsg& routed, uint64_t kind);

  // Keys of recently flooded messages (type, origin, request, target), so that each is forwarded
  // or handled once.
  // Allocated on the first flood: most modules never flood, and a module's idle state stays small.
  struct Recent {
    std::array<uint64_t, 16> keys{};
    int next = 0;
  };
  std::unique_ptr<Recent> recent_;
};

}  // namespace datomsim::algorithms

#include "algorithms/routing_impl.h"
