// Messages for a module that is not a neighbour, carried hop by hop between latched neighbours.
//
// Deformation requests of Algorithm 1 go from the mobile to modules up to two cells away. Each
// hop forwards the message through the latched connector whose neighbour is nearest to the
// target cell, if nearer than itself (greedy geographic routing); where no neighbour is nearer,
// it floods to all latched neighbours with a hop limit, each module forwarding a given message
// once. Delivery happens at the module in the target cell.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "geometry/cell.h"
#include "program/module_program.h"

namespace datomsim::algorithms {

struct RoutedMsg {
  geometry::Cell target;
  geometry::Cell origin;  // where the answer goes
  uint32_t request = 0;   // the origin's request number
  int8_t axis = -1;       // a world piston axis, for DeformMsg
  int8_t hopsLeft = 0;    // for flooding
  bool flooding = false;
};

struct DeformMsg : RoutedMsg {
  static constexpr std::string_view kName = "DeformMsg";
};
struct AckDeform : RoutedMsg {
  static constexpr std::string_view kName = "AckDeform";
};
struct ReleaseMsg : RoutedMsg {
  static constexpr std::string_view kName = "ReleaseMsg";
};
struct AckRelease : RoutedMsg {
  static constexpr std::string_view kName = "AckRelease";
};

class Router {
 public:
  static constexpr int8_t kFloodHops = 8;

  // Sends towards routed.target from this module, choosing the next hop.
  template <typename T>
  void send(program::ModuleContext& context, T routed, int arrivedThrough = -1) {
    forward(context, routed, arrivedThrough, [&](int connector, const RoutedMsg& next) {
      T copy = routed;
      static_cast<RoutedMsg&>(copy) = next;
      return context.send(connector, program::Message::of(copy));
    });
  }

 private:
  template <typename Send>
  void forward(program::ModuleContext& context, const RoutedMsg& routed, int arrivedThrough,
               Send&& sendThrough);

  bool seen(const RoutedMsg& routed);

  // Keys of recently flooded messages (origin, request, target), so that each is forwarded once.
  // Allocated on the first flood: most modules never flood, and a module's idle state stays small.
  struct Recent {
    std::array<uint64_t, 16> keys{};
    int next = 0;
  };
  std::unique_ptr<Recent> recent_;
};

}  // namespace datomsim::algorithms

#include "algorithms/routing_impl.h"
