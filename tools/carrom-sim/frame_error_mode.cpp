#include "frame_error_mode.hpp"

#include "sim_cli.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/journal_replay.hpp"
#include "carrom/scene.hpp"
#include "carrom/trajectory.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace carrom {
namespace {

using Json = nlohmann::json;

using sim_cli::kExitBadInput;
// A frame jumped when a body moved more than this many times its exact displacement between the
// two frames' shot times, plus kJumpSlackPx.
constexpr double kJumpFactor = 3.0;
constexpr double kJumpSlackPx = 2.0;
// The board drawn at rest equals the server's when every coin is within this of it.
constexpr double kFinalTolerancePx = 0.005;
// A freeze counts when the drawn board stayed the same for longer than this many frame
// intervals (the median interval of the log) while the stroke was still moving.
constexpr double kFreezeIntervals = 2.0;
// The server's last keyframe of a stroke holds the board after the rules: the striker on the next
// baseline, returned pieces placed. A client interpolates those bodies there from its last
// snapshot of the stroke, so they are compared only while they move in the exact trajectory and
// not in the stroke's last 1/60 s (a margin of one 60 Hz snapshot interval).
constexpr double kLastIntervalS = 1.0 / 60.0;

struct Frame {
    double ms = 0.0;
    long index = 0;
    int turn = -1;
    double t_s = 0.0;
    std::map<int, Vec2> bodies;
};

struct Stroke {
    int turn = 0;
    int seat = 0;
    Trajectory trajectory;
    double end_s = 0.0;
    std::map<int, Vec2> final_board; // coins as the server's last keyframe of it holds them
    std::vector<int> placed;         // bodies the rules move at the end: striker, returned
};

struct Failure {
    std::string code;
    std::string message;
};

int fail(std::ostream& err, const std::string& code, const std::string& message) {
    sim_cli::print_json(err, proto::error_to_json({code, "", message}), false);
    return kExitBadInput;
}

// The frame lines of the log ("kind": "frame"); other lines are skipped.
bool read_frames(std::istream& in, std::vector<Frame>& frames, Failure& failure) {
    std::string line;
    long number = 0;
    while (std::getline(in, line)) {
        ++number;
        const Json j = Json::parse(line, nullptr, /*allow_exceptions=*/false);
        const auto bad = [&](const std::string& why) {
            failure = {"bad_frame_log",
                       "line " + std::to_string(number) + " of the frame log " + why + "."};
            return false;
        };
        if (!j.is_object() || !j.contains("kind") || !j["kind"].is_string()) {
            return bad("is not a JSON object with a \"kind\"");
        }
        if (j["kind"] != "frame") {
            continue;
        }
        Frame f;
        try {
            f.ms = j.at("ms").get<double>();
            f.index = j.at("frame").get<long>();
            f.turn = j.at("turn").get<int>();
            f.t_s = j.at("t").get<double>();
            for (const Json& b : j.at("bodies")) {
                f.bodies[b.at(0).get<int>()] = {b.at(1).get<double>(), b.at(2).get<double>()};
            }
        } catch (const Json::exception&) {
            return bad("lacks ms, frame, turn, t or bodies ([id, x, y] each)");
        }
        frames.push_back(std::move(f));
    }
    if (in.bad()) {
        failure = {"io_error", "reading the frame log failed."};
        return false;
    }
    return true;
}

std::vector<Stroke> strokes_of(const proto::ReplayResult& replayed) {
    std::vector<Stroke> strokes;
    for (const proto::ReplayStep& step : replayed.steps) {
        const rules::ShotOutcome& o = step.outcome;
        if (!o.shot_taken || step.refused) {
            continue;
        }
        Stroke s;
        s.turn = o.turn_number;
        s.seat = o.seat;
        s.trajectory = o.physics.trajectory;
        s.end_s = o.physics.end_time_s;
        for (const Body& b : o.physics.bodies) {
            if (!b.pocketed && b.id != kStrikerId) {
                s.final_board[b.id] = b.pos_px;
            }
        }
        s.placed.push_back(kStrikerId);
        for (const rules::ReturnedPiece& r : o.returned) {
            s.final_board[r.id] = r.pos_px;
            s.placed.push_back(r.id);
        }
        strokes.push_back(std::move(s));
    }
    return strokes;
}

double median_interval_ms(const std::vector<Frame>& frames) {
    std::vector<double> gaps;
    for (std::size_t i = 1; i < frames.size(); ++i) {
        if (frames[i].index == frames[i - 1].index + 1) {
            gaps.push_back(frames[i].ms - frames[i - 1].ms);
        }
    }
    if (gaps.empty()) {
        return 0.0;
    }
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2), gaps.end());
    return gaps[gaps.size() / 2];
}

// Exact positions at t_s, by id, of the unpocketed bodies, less those the rules move at the end
// once they rest.
std::map<int, Vec2> exact_at(const PhysicsConfig& physics, const Stroke& s, double t_s) {
    std::map<int, Vec2> out;
    const bool last_interval = t_s >= s.end_s - kLastIntervalS;
    for (const Body& b : state_at(physics, s.trajectory, t_s)) {
        const bool placed = std::find(s.placed.begin(), s.placed.end(), b.id) != s.placed.end();
        if (!b.pocketed && !(placed && (last_interval || b.vel_px_s == Vec2{}))) {
            out[b.id] = b.pos_px;
        }
    }
    return out;
}

struct Totals {
    long samples = 0;
    double sum_sq = 0.0;
    double max_px = 0.0;
    int jumps = 0;
    int freezes = 0;
    double longest_freeze_ms = 0.0;
    int finals_equal = 0;
    int finals_checked = 0;
};

Json measure(const PhysicsConfig& physics, const Stroke& s, const std::vector<Frame>& frames,
             double interval_ms, Totals& totals) {
    long samples = 0;
    double sum_sq = 0.0;
    double max_px = 0.0;
    int jumps = 0;
    double largest_jump_px = 0.0;
    int freezes = 0;
    double longest_freeze_ms = 0.0;
    long drawn_frames = 0;
    const Frame* previous = nullptr;
    std::map<int, Vec2> previous_exact;
    double still_since_ms = -1.0; // ms of the last frame that changed, while nothing changes
    const Frame* last = nullptr;
    for (const Frame& f : frames) {
        if (f.turn != s.turn) {
            continue;
        }
        ++drawn_frames;
        last = &f;
        const bool moving = f.t_s >= 0.0 && f.t_s < s.end_s;
        std::map<int, Vec2> exact;
        if (moving) {
            exact = exact_at(physics, s, f.t_s);
            for (const auto& [id, p] : f.bodies) {
                const auto it = exact.find(id);
                if (it == exact.end()) {
                    continue; // pocketed in the exact trajectory: drawn as it falls
                }
                const double e = length(p - it->second);
                sum_sq += e * e;
                max_px = std::max(max_px, e);
                ++samples;
            }
        }
        const bool adjacent = previous != nullptr && previous->index + 1 == f.index;
        if (adjacent && moving && !previous_exact.empty()) {
            for (const auto& [id, p] : f.bodies) {
                const auto was = previous->bodies.find(id);
                const auto now_exact = exact.find(id);
                const auto was_exact = previous_exact.find(id);
                if (was == previous->bodies.end() || now_exact == exact.end() ||
                    was_exact == previous_exact.end()) {
                    continue;
                }
                const double drawn = length(p - was->second);
                const double limit =
                    kJumpFactor * length(now_exact->second - was_exact->second) + kJumpSlackPx;
                if (drawn > limit) {
                    ++jumps;
                    largest_jump_px = std::max(largest_jump_px, drawn);
                }
            }
        }
        if (adjacent && moving && f.t_s > 0.0 && f.bodies == previous->bodies) {
            if (still_since_ms < 0.0) {
                still_since_ms = previous->ms;
            }
        } else if (still_since_ms >= 0.0) {
            const double held = f.ms - still_since_ms;
            if (held > kFreezeIntervals * interval_ms) {
                ++freezes;
                longest_freeze_ms = std::max(longest_freeze_ms, held);
            }
            still_since_ms = -1.0;
        }
        previous = &f;
        previous_exact = moving ? std::move(exact) : std::map<int, Vec2>{};
    }
    Json out{{"turn", s.turn},
             {"seat", s.seat},
             {"end_s", s.end_s},
             {"frames", drawn_frames},
             {"samples", samples},
             {"rms_px", samples > 0 ? std::sqrt(sum_sq / static_cast<double>(samples)) : 0.0},
             {"max_px", max_px},
             {"jumps", jumps},
             {"largest_jump_px", largest_jump_px},
             {"freezes", freezes},
             {"longest_freeze_ms", longest_freeze_ms}};
    totals.samples += samples;
    totals.sum_sq += sum_sq;
    totals.max_px = std::max(totals.max_px, max_px);
    totals.jumps += jumps;
    totals.freezes += freezes;
    totals.longest_freeze_ms = std::max(totals.longest_freeze_ms, longest_freeze_ms);
    if (last == nullptr || last->t_s < s.end_s) {
        out["final"] = nullptr; // never drawn at rest
        return out;
    }
    double worst = 0.0;
    std::vector<int> missing;
    std::vector<int> extra;
    for (const auto& [id, p] : s.final_board) {
        const auto it = last->bodies.find(id);
        if (it == last->bodies.end()) {
            missing.push_back(id);
        } else {
            worst = std::max({worst, std::abs(it->second.x - p.x), std::abs(it->second.y - p.y)});
        }
    }
    for (const auto& [id, p] : last->bodies) {
        if (id != kStrikerId && !s.final_board.contains(id)) {
            extra.push_back(id);
        }
    }
    const bool equal = missing.empty() && extra.empty() && worst <= kFinalTolerancePx;
    out["final"] = {
        {"equal", equal}, {"max_difference_px", worst}, {"missing", missing}, {"extra", extra}};
    ++totals.finals_checked;
    totals.finals_equal += equal ? 1 : 0;
    return out;
}

} // namespace

int run_frame_error_mode(const std::string& frames_path, const std::string& journal_path,
                         std::ostream& out, std::ostream& err, bool pretty) {
    std::ifstream journal_file(journal_path, std::ios::binary);
    if (journal_path.empty() || journal_path == "-" || !journal_file) {
        return fail(err, "io_error", "cannot open the journal file '" + journal_path + "'");
    }
    std::ostringstream text;
    text << journal_file.rdbuf();
    const auto journal = proto::decode_journal_text(text.str());
    if (!journal.ok()) {
        sim_cli::print_json(err, proto::error_to_json(*journal.error), false);
        return kExitBadInput;
    }
    proto::ReplayOptions options;
    options.record_trajectory = true;
    const proto::ReplayResult replayed = proto::replay(journal.value, options);
    if (replayed.error) {
        sim_cli::print_json(err, proto::error_to_json(*replayed.error), false);
        return kExitBadInput;
    }
    std::ifstream frames_file(frames_path, std::ios::binary);
    if (!frames_file) {
        return fail(err, "io_error", "cannot open the frame log '" + frames_path + "'");
    }
    std::vector<Frame> frames;
    Failure failure;
    if (!read_frames(frames_file, frames, failure)) {
        return fail(err, failure.code, failure.message);
    }
    const double interval_ms = median_interval_ms(frames);
    const PhysicsConfig& physics = journal.value.created.physics;
    Totals totals;
    Json turns = Json::array();
    for (const Stroke& s : strokes_of(replayed)) {
        turns.push_back(measure(physics, s, frames, interval_ms, totals));
    }
    sim_cli::print_json(
        out,
        {{"match", journal.value.created.match_id},
         {"frames", frames.size()},
         {"frame_interval_ms", interval_ms},
         {"strokes", std::move(turns)},
         {"samples", totals.samples},
         {"rms_px", totals.samples > 0
                        ? std::sqrt(totals.sum_sq / static_cast<double>(totals.samples))
                        : 0.0},
         {"max_px", totals.max_px},
         {"jumps", totals.jumps},
         {"freezes", totals.freezes},
         {"longest_freeze_ms", totals.longest_freeze_ms},
         {"finals_checked", totals.finals_checked},
         {"finals_equal", totals.finals_equal}},
        pretty);
    return 0;
}

} // namespace carrom
