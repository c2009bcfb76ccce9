// Building and replaying match journals (see journal_replay.hpp).

#include "carrom/proto/journal_replay.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/result_hash.hpp"
#include "carrom/rules/state_hash.hpp"

#include <type_traits>
#include <utility>

namespace carrom::proto {
namespace {

std::uint64_t hash_of(const SimResult& physics) {
    ResultHash hash;
    hash.add(physics);
    return hash.value();
}

std::string text_of(const std::vector<int>& values) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += (i > 0 ? ", " : "") + std::to_string(values[i]);
    }
    return out + "]";
}

std::string text_of(const std::vector<rules::RuleCode>& codes) {
    std::string out = "[";
    for (std::size_t i = 0; i < codes.size(); ++i) {
        out += (i > 0 ? ", " : "") + std::string(rules::to_string(codes[i]));
    }
    return out + "]";
}

std::string text_of(const std::optional<int>& team) {
    return team ? "team " + std::to_string(*team) : "none";
}

std::string text_of(const std::optional<rules::BoardResult>& b) {
    if (!b) {
        return "none";
    }
    return "board " + std::to_string(b->board) + " won by " + text_of(b->winner_team) + " (" +
           std::to_string(b->points) + " points, " + std::string(rules::to_string(b->reason)) + ")";
}

std::string text_of(const std::optional<rules::GameResult>& g) {
    if (!g) {
        return "none";
    }
    return "won by " + text_of(g->winner_team) + " (" + std::string(rules::to_string(g->reason)) +
           ")";
}

template <class T>
void compare(std::vector<std::string>& out, std::string_view field, const T& journal,
             const T& replayed) {
    if (!(journal == replayed)) {
        out.push_back(std::string(field) + ": journal " + text_of(journal) + ", replay " +
                      text_of(replayed));
    }
}

void compare_hash(std::vector<std::string>& out, std::string_view field, std::uint64_t journal,
                  std::uint64_t replayed) {
    if (journal != replayed) {
        out.push_back(std::string(field) + ": journal " + hash_to_hex(journal) + ", replay " +
                      hash_to_hex(replayed));
    }
}

void compare_int(std::vector<std::string>& out, std::string_view field, int journal, int replayed) {
    if (journal != replayed) {
        out.push_back(std::string(field) + ": journal " + std::to_string(journal) + ", replay " +
                      std::to_string(replayed));
    }
}

std::vector<std::string> differences(const OutcomeRecord& journal, const OutcomeRecord& replay) {
    std::vector<std::string> out;
    compare(out, "pocketed", journal.pocketed, replay.pocketed);
    compare(out, "fouls", journal.fouls, replay.fouls);
    compare(out, "scores", journal.scores, replay.scores);
    compare_int(out, "next_seat", journal.next_seat, replay.next_seat);
    compare(out, "board_end", journal.board_end, replay.board_end);
    compare(out, "game_end", journal.game_end, replay.game_end);
    compare_hash(out, "state_hash", journal.state_hash, replay.state_hash);
    return out;
}

// The input an entry carries, as the rules take it.
struct Input {
    int turn = 0;
    int seat = 0;
    const OutcomeRecord* record = nullptr;
    const StrokeEntry* stroke = nullptr;
    const ClockExpiredEntry* expiry = nullptr;
    const ForfeitEntry* forfeit = nullptr;
};

std::optional<Input> input_of(const JournalEvent& event) {
    return std::visit(
        [](const auto& e) -> std::optional<Input> {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, StrokeEntry>) {
                return Input{e.turn, e.seat, &e.outcome, &e, nullptr, nullptr};
            } else if constexpr (std::is_same_v<T, ClockExpiredEntry>) {
                return Input{e.turn, e.seat, &e.outcome, nullptr, &e, nullptr};
            } else if constexpr (std::is_same_v<T, ForfeitEntry>) {
                return Input{e.turn, e.seat, &e.outcome, nullptr, nullptr, &e};
            } else {
                return std::nullopt;
            }
        },
        event);
}

std::optional<Error> check_head(const MatchCreated& c) {
    const auto bad = [](std::string path, std::string message) {
        return Error{std::string(replay_code::kBadJournal), std::move(message), std::move(path)};
    };
    if (auto problem = rules::validate_rules_config(c.rules)) {
        return bad("match.rules." + problem->field, problem->message);
    }
    if (auto problem = validate_config(c.physics)) {
        return bad("match.physics." + problem->field, problem->message);
    }
    if (c.seats.size() != static_cast<std::size_t>(c.rules.seat_count)) {
        return bad("match.seats", "the journal names " + std::to_string(c.seats.size()) +
                                      " seats for a game of " + std::to_string(c.rules.seat_count));
    }
    return std::nullopt;
}

} // namespace

OutcomeRecord record_outcome(const rules::ShotOutcome& outcome, const rules::MatchState& after) {
    OutcomeRecord record;
    record.state_hash = rules::hash_match_state(after);
    record.pocketed = outcome.pocketed;
    for (const rules::Foul& foul : outcome.fouls) {
        record.fouls.push_back(foul.code);
    }
    record.scores = after.scores;
    record.next_seat = outcome.next_seat;
    record.board_end = outcome.board_end;
    record.game_end = outcome.game_end;
    return record;
}

JournalEntry stroke_entry(std::int64_t time_ms, const rules::PlayResult& result) {
    const rules::ShotOutcome& o = result.outcome;
    return JournalEntry{time_ms, StrokeEntry{o.turn_number, o.seat, o.shot, hash_of(o.physics),
                                             record_outcome(o, result.state)}};
}

JournalEntry clock_expired_entry(std::int64_t time_ms, const rules::PlayResult& result) {
    const rules::ShotOutcome& o = result.outcome;
    return JournalEntry{time_ms,
                        ClockExpiredEntry{o.turn_number, o.seat, record_outcome(o, result.state)}};
}

JournalEntry forfeit_entry(std::int64_t time_ms, const rules::PlayResult& result,
                           ForfeitReason reason) {
    const rules::ShotOutcome& o = result.outcome;
    return JournalEntry{
        time_ms, ForfeitEntry{o.turn_number, o.seat, reason, record_outcome(o, result.state)}};
}

rules::MatchState initial_state(const MatchCreated& created) {
    rules::MatchState state = rules::new_match(created.rule_set, created.rules, created.physics);
    state.turn_number = created.first_turn;
    return state;
}

std::optional<Error> check_versions(const MatchCreated& created) {
    const JournalVersions& v = created.versions;
    if (v.physics == kPhysicsVersion && v.rules == rules::kRulesVersion) {
        return std::nullopt;
    }
    return Error{std::string(replay_code::kVersionMismatch),
                 "the journal was written with physics version " + std::to_string(v.physics) +
                     " and rules version " + std::to_string(v.rules) +
                     "; this build has physics version " + std::to_string(kPhysicsVersion) +
                     " and rules version " + std::to_string(rules::kRulesVersion),
                 "match.versions"};
}

ReplayResult replay(const MatchJournal& journal, const ReplayOptions& options) {
    ReplayResult out;
    if ((out.error = check_versions(journal.created)) ||
        (out.error = check_head(journal.created))) {
        return out;
    }
    out.state = initial_state(journal.created);
    ExactEngine engine(journal.created.physics);
    rules::PlayOptions play_options;
    play_options.record_trajectory = options.record_trajectory;
    for (std::size_t i = 0; i < journal.entries.size(); ++i) {
        const std::optional<Input> input = input_of(journal.entries[i].event);
        if (!input) {
            continue;
        }
        ReplayStep step;
        step.entry = i;
        rules::PlayResult r;
        if (input->stroke != nullptr) {
            r = rules::play_shot(out.state, input->seat, input->stroke->shot, engine, play_options);
        } else if (input->expiry != nullptr) {
            r = rules::shot_clock_expired(out.state, input->seat);
        } else {
            r = rules::forfeit(out.state, input->seat);
        }
        compare_int(step.differences, "turn", input->turn, out.state.turn_number);
        if (r.error) {
            step.refused = r.error;
            step.differences.push_back(
                "the rules refuse it: " + std::string(rules::to_string(r.error->code)) + " (" +
                r.error->message + ")");
            ++out.mismatches;
            out.steps.push_back(std::move(step));
            return out;
        }
        step.replayed = record_outcome(r.outcome, r.state);
        const auto more = differences(*input->record, step.replayed);
        step.differences.insert(step.differences.end(), more.begin(), more.end());
        if (input->stroke != nullptr) {
            step.result_hash = hash_of(r.outcome.physics);
            compare_hash(step.differences, "result_hash", input->stroke->result_hash,
                         step.result_hash);
        }
        if (!options.keep_physics && !options.record_trajectory) {
            r.outcome.physics = {};
        }
        out.mismatches += step.differences.empty() ? 0 : 1;
        step.outcome = std::move(r.outcome);
        out.steps.push_back(std::move(step));
        out.state = std::move(r.state);
        if (out.state.phase == rules::Phase::BoardOver) {
            out.state = rules::start_next_board(out.state);
        }
    }
    out.complete = true;
    return out;
}

} // namespace carrom::proto
