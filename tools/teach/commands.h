// A pendant operation as a UI sends it: {"op": NAME, ...arguments}. The web
// page posts these; the same names are the Pendant's methods, so a request
// is one call. Malformed requests (unknown op, missing or mistyped
// argument) come back with Outcome::badRequest set, nothing done.
//
//   {"op":"jog","motor":0,"delta":10}     {"op":"set","motor":0,"value":100}
//   {"op":"moveTo","values":[...]}         {"op":"gripper","close":true}
//   {"op":"teach","name":"P1"}            {"op":"reteach","name":"P1"}
//   {"op":"delete","name":"P1"}           {"op":"rename","from":"P1","to":"P2"}
//   {"op":"goTo","name":"P1"}             {"op":"input","line":3}  (toggles)
//   {"op":"output","line":3,"on":true}    {"op":"reset"}
//   {"op":"readPosition"}                 {"op":"reload"}
//   {"op":"jogCartesian","frame":"world","axis":"X","amount":10}  (frame "world" or "tool"; degrees for a turn)
#pragma once

#include <nlohmann/json.hpp>

#include "tools/teach/pendant.h"

namespace rs::teach {

Outcome applyCommand(Pendant& pendant, const nlohmann::json& request);

}  // namespace rs::teach
