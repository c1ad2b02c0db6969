// What a run says about where parts go (docs/models.md, "Objects in the
// gripper"): a gripper that closed round a fixture, and a part that
// settled after it was let go — the one place that words them and decides
// which are worth a warning. The trace, the summary and the run's
// diagnostics (`run`, `check`, `check --strict`) read it here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/run/run.h"

namespace rs::runtime {

/// "block (object 3)": an object as the run's messages name it, by
/// `number` where given (fed parts: Rig::objectNumber), else index + 1.
std::string objectText(const workcell::Workcell& cell, std::size_t o, std::uint32_t number = 0);

/// What a let-go settled on: "pallet (object 2)", "the belt of conveyor
/// (object 1)", "the floor", "nothing" (meaningful for a let-go).
std::string supportText(const GraspEvent& e, const workcell::Workcell& cell);

/// The trace's words for a let-go's settling: "settles on pallet (object
/// 2), dropped 29.7", "settles on pallet (object 2), raised 0.16 out of
/// it", "settles on pallet (object 2)" (it was let go resting on it);
/// "stays where it was let go: nothing under it". Lengths to 2 decimals.
std::string settleText(const GraspEvent& e, const workcell::Workcell& cell);

/// "closes round pallet (object 2), a fixture: takes nothing".
std::string fixtureCloseText(const EmptyClose& e, const workcell::Workcell& cell);

/// "block (object 3) dropped 29.7 onto pallet (object 2): it was let go above it".
std::string longDropText(const GraspEvent& e, const workcell::Workcell& cell);

/// The run's warnings about placing, in run order by kind: each close
/// round a fixture (code `gripper-closed-on-fixture`), then each drop
/// longer than kLongDrop (code `part-dropped`), at the instruction that
/// did it (the first Rig::kKeptPlacingNotes of each).
std::vector<diag::Diagnostic> placingWarnings(const Run& run, const std::string& file);

}  // namespace rs::runtime
