#include "carrom/client/board_report.hpp"

#include "carrom/client/board_summary_text.hpp"
#include "carrom/client/game_over_text.hpp"
#include "carrom/proto/types.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>

namespace carrom::client {
namespace {

// [{"text", "tone"}], oldest first.
nlohmann::json said_json(const std::deque<HudLine>& said) {
    static constexpr std::array<const char*, 4> kTones{"info", "good", "foul", "error"};
    nlohmann::json lines = nlohmann::json::array();
    for (const HudLine& line : said) {
        lines.push_back(
            {{"text", line.text}, {"tone", kTones.at(static_cast<std::size_t>(line.tone))}});
    }
    return lines;
}

} // namespace

std::string board_report_json(const MatchView& view, const std::vector<RenderedBody>& bodies,
                              const ScreenMapping& mapping, const ReportContext& context) {
    nlohmann::json j;
    j["room"] = view.code;
    j["you"] = view.you;
    j["turn"] = view.turn;
    j["phase"] = std::string(proto::to_string(view.phase));
    j["flipped"] = mapping.bottom == rules::Side::Top;
    j["bottom_side"] = std::string(rules::to_string(mapping.bottom));
    j["window"] = {{"w", context.window_w}, {"h", context.window_h}};
    j["board"] = {{"x", mapping.origin_x},
                  {"y", mapping.origin_y},
                  {"side", mapping.length_to_screen(mapping.board_size_px)}};
    j["shots_seen"] = context.shots_seen;
    nlohmann::json scores = nlohmann::json::array();
    for (const SeatView& s : view.seats) {
        scores.push_back(s.score);
    }
    j["scores"] = scores;
    nlohmann::json names = nlohmann::json::array();
    for (const SeatView& s : view.seats) {
        names.push_back(s.occupied ? s.name : std::string());
    }
    j["names"] = names;
    nlohmann::json list = nlohmann::json::array();
    for (const RenderedBody& b : bodies) {
        const Vec2 s = mapping.to_screen(b.pos_px);
        list.push_back({{"id", b.id},
                        {"kind", std::string(proto::body_kind_name(b.kind))},
                        {"x", b.pos_px.x},
                        {"y", b.pos_px.y},
                        {"screen_x", s.x},
                        {"screen_y", s.y},
                        {"scale", b.scale},
                        {"alpha", b.alpha}});
    }
    j["prediction"] = {{"strokes", context.prediction.strokes},
                       {"corrections", context.prediction.corrections},
                       {"max_difference_px", context.prediction.max_difference_px}};
    j["bodies"] = list;
    if (view.board_summary) {
        const BoardSummaryText t = board_summary_text(view);
        j["board_summary"] = {{"title", t.title}, {"points", t.points}, {"colours", t.colours}};
    } else {
        j["board_summary"] = nullptr;
    }
    j["said"] = said_json(context.said != nullptr ? *context.said : std::deque<HudLine>{});
    if (context.overlay) {
        const Rect& o = *context.overlay;
        j["overlay"] = {{"x", o.x}, {"y", o.y}, {"w", o.w}, {"h", o.h}};
    } else {
        j["overlay"] = nullptr;
    }
    j["ui"] = nlohmann::json::parse(context.ui_json, nullptr, false);
    return j.dump();
}

std::string final_state_json(const MatchView& view, const std::vector<BodyState>& board,
                             const std::deque<HudLine>& said) {
    nlohmann::json j;
    j["room"] = view.code;
    j["you"] = view.you;
    j["winner"] = view.result ? view.result->winner : view.winner;
    j["reason"] = view.result ? game_end_name(*view.result) : std::string();
    nlohmann::json scores = nlohmann::json::array();
    if (view.result) {
        for (const int s : view.result->scores) {
            scores.push_back(s);
        }
    }
    j["scores"] = scores;
    std::vector<BodyState> sorted = board;
    std::sort(sorted.begin(), sorted.end(),
              [](const BodyState& a, const BodyState& b) { return a.id < b.id; });
    nlohmann::json list = nlohmann::json::array();
    for (const BodyState& b : sorted) {
        list.push_back({{"id", b.id},
                        {"kind", std::string(proto::body_kind_name(b.kind))},
                        {"x", b.pos_px.x},
                        {"y", b.pos_px.y},
                        {"pocketed", b.pocketed}});
    }
    j["bodies"] = list;
    if (view.phase == proto::Phase::GameOver) {
        const GameOverText t = game_over_text(view, false);
        j["game_over"] = {{"title", t.title},
                          {"reason", t.reason},
                          {"score", t.score},
                          {"can_rematch", t.can_rematch},
                          {"opponent_left", t.opponent_left},
                          {"waiting", t.waiting}};
    } else {
        j["game_over"] = nullptr;
    }
    j["said"] = said_json(said);
    return j.dump();
}

} // namespace carrom::client
