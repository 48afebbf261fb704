// A module that sits on one hop between an initiator socket and a target socket (a monitor, a
// protocol checker, a tracer): the initiator side binds to hop_in(), hop_out() binds to the target,
// and the module passes every interface through (b_transport, nb_transport both ways, DMI requests
// and invalidations, debug transport). The board places one on each of its inner hops when it is
// given one (board/rc2000.h, InnerHops); nothing here is required of the module beyond passing
// everything on unchanged in value and time.
#pragma once

#include <tlm>

namespace rc::tlmx {

class HopInterposer {
 public:
  virtual ~HopInterposer() = default;
  virtual tlm::tlm_target_socket<>& hop_in() = 0;      // bound by the hop's initiator side
  virtual tlm::tlm_initiator_socket<>& hop_out() = 0;  // binds to the hop's target
};

}  // namespace rc::tlmx
