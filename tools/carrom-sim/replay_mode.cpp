// `carrom-sim --replay`: verifies a match journal (see replay_mode.hpp). Prints
//   {"match", "room", "rule_set", "steps": [<step>, ...], "mismatches", "complete", "scores",
//    "result"}
// where each step is a stroke, clock expiry or forfeit as replayed, with "matches" and, when it
// does not match, the "differences" from what the journal recorded.

#include "replay_mode.hpp"

#include "sim_cli.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/journal_replay.hpp"
#include "carrom/proto/match_json.hpp"
#include "carrom/rules/rule_error.hpp"

#include <iostream>
#include <string>

namespace carrom {
namespace {

using Json = nlohmann::json;

constexpr int kExitMismatch = 1;
using sim_cli::kExitBadInput;

Json step_to_json(const proto::ReplayStep& step, const proto::JournalEntry& entry) {
    Json out = {{"entry", step.entry},
                {"type", std::string(proto::event_type(entry.event))},
                {"time_ms", entry.time_ms},
                {"turn", step.outcome.turn_number},
                {"seat", step.outcome.seat}};
    if (const auto* stroke = std::get_if<proto::StrokeEntry>(&entry.event)) {
        out["shot"] = proto::rules_shot_to_json(stroke->shot);
        out["result_hash"] = proto::hash_to_hex(step.result_hash);
    }
    if (step.refused) {
        out["refused"] = {{"code", std::string(rules::to_string(step.refused->code))},
                          {"message", step.refused->message}};
    } else {
        out["outcome"] = proto::outcome_record_to_json(step.replayed);
    }
    out["matches"] = step.differences.empty();
    if (!step.differences.empty()) {
        out["differences"] = step.differences;
    }
    return out;
}

} // namespace

int run_replay_mode(std::istream& in, std::ostream& out, std::ostream& err, bool pretty) {
    std::string text;
    char buffer[65536];
    while (in && text.size() <= proto::kMaxJournalBytes) {
        in.read(buffer, sizeof buffer);
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) {
        sim_cli::print_json(err, proto::error_to_json({"io_error", "reading the journal failed"}),
                            false);
        return kExitBadInput;
    }
    const auto journal = proto::decode_journal_text(text);
    if (!journal.ok()) {
        sim_cli::print_json(err, proto::error_to_json(*journal.error), false);
        return kExitBadInput;
    }
    const proto::ReplayResult r = proto::replay(journal.value);
    if (r.error) {
        sim_cli::print_json(err, proto::error_to_json(*r.error), false);
        return kExitBadInput;
    }
    const proto::MatchCreated& created = journal.value.created;
    Json steps = Json::array();
    for (const proto::ReplayStep& step : r.steps) {
        steps.push_back(step_to_json(step, journal.value.entries[step.entry]));
    }
    sim_cli::print_json(
        out,
        {{"match", created.match_id},
         {"room", created.room_code},
         {"rule_set", std::string(rules::to_string(created.rule_set))},
         {"entries", journal.value.entries.size()},
         {"steps", std::move(steps)},
         {"mismatches", r.mismatches},
         {"complete", r.complete},
         {"scores", r.state.scores},
         {"result", r.state.result ? proto::game_result_to_json(*r.state.result) : Json(nullptr)}},
        pretty);
    return r.ok() ? 0 : kExitMismatch;
}

} // namespace carrom
