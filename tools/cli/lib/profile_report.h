// `robotsim run --profile`: a run's profile (runtime/run/profile.h) as text
// for people, and as the "profile" member of the JSON summary.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "runtime/run/profile.h"
#include "vm/image.h"

namespace rs::cli {

void printTextProfile(std::ostream& out, const runtime::Profile& profile);
/// Times in whole microseconds ("_us"), exactly as simulated.
nlohmann::ordered_json profileJson(const runtime::Profile& profile);

}  // namespace rs::cli
