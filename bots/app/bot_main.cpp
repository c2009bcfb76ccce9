// carrom-bot: a headless player. Creates a room, joins one by code, or asks for a quick match,
// plays --games games with a strategy, then prints a JSON summary on stdout. Exit status 0 when
// it played its games to the end, 1 otherwise (the summary's "failure" says why).
#include "carrom/bots/bot_runner.hpp"
#include "carrom/bots/scripted_strategy.hpp"
#include "carrom/cli/room_request_flags.hpp"
#include "carrom/net/identity_file.hpp"
#include "carrom/proto/types.hpp"
#include "trace_writer.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace {

using namespace carrom;

nlohmann::json summary_json(const bots::BotSummary& s, const bots::Strategy& strategy) {
    const bots::Strategy::SearchTotals totals = strategy.search_totals();
    nlohmann::json errors = nlohmann::json::object();
    for (const auto& [code, count] : s.errors) {
        errors[code] = count;
    }
    std::string result = "none";
    if (s.games > 0) {
        result = s.seat < 0          ? "watched"
                 : s.wins > s.losses ? "won"
                 : s.losses > s.wins ? "lost"
                                     : "drawn";
    }
    return {{"ok", s.failure.empty() && s.finished},
            {"strategy", strategy.name()},
            {"room", s.room_code},
            {"seat", s.seat},
            {"team", s.team},
            {"games", s.games},
            {"shots", s.shots},
            {"result", result},
            {"wins", s.wins},
            {"losses", s.losses},
            {"draws", s.draws},
            {"scores", s.scores},
            {"reason", s.last_reason},
            {"snapshots", s.snapshots},
            {"keyframes", s.keyframes},
            {"seq_gaps", s.seq_gaps},
            {"unrepaired_gaps", s.unrepaired_gaps},
            {"resumes", s.resumes},
            {"redirects", s.redirects},
            {"decode_errors", s.decode_errors},
            {"errors", errors},
            {"failure", s.failure},
            {"candidates", totals.candidates},
            {"think_s", totals.seconds},
            {"candidates_per_s",
             totals.seconds > 0.0 ? static_cast<double>(totals.candidates) / totals.seconds : 0.0}};
}

std::optional<std::string> read_file(const std::string& path, std::string& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return "Could not open the script file '" + path + "'.";
    }
    std::ostringstream text;
    text << in.rdbuf();
    out = text.str();
    return std::nullopt;
}

} // namespace

int main(int argc, char** argv) {
    bots::BotConfig config;
    bots::StrategyOptions strategy_options;
    cli::RoomRequestFlags room_flags;
    std::string script_path;
    std::string log_level = "warn";
    int target_points = 0;
    int boards = 0;
    double shot_clock_s = -1.0;
    double timeout_s = 3600.0;
    double resume_for_s = 130.0;
    int think_ms = 300;

    CLI::App app{"carrom-bot: a headless carrom player (prints a JSON summary at the end)"};
    app.option_defaults()->always_capture_default();
    app.add_option("--url", config.url, "Server address, ws://HOST:PORT or wss://HOST:PORT");
    app.add_option("--ca-file", config.connection.ca_file,
                   "wss://: trust the certificate authorities in this PEM file too");
    app.add_option("--name", config.name, "Player name (1-24 bytes)");
    std::string identity_path;
    app.add_option("--identity", identity_path,
                   "Play as the identified player whose key is in this file (created with a new "
                   "key when absent; docs/ratings.md); without it, a guest");
    cli::add_room_request_flags(app, room_flags);
    app.add_option("--target-points", target_points, "--create: points to win (0 = default)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--boards", boards, "--create: most boards (0 = default)")
        ->check(CLI::Range(0, 99));
    app.add_option("--shot-clock", shot_clock_s,
                   "--create: seconds per stroke (0 = off, -1 = server default)")
        ->check(CLI::Range(-1.0, 600.0));
    app.add_flag("--rated", config.create.rated,
                 "--create: a rated room (needs --identity; singles, no bot; docs/ratings.md)");
    app.add_option("--strategy", strategy_options.name, "Strategy")
        ->check(CLI::IsMember(bots::strategy_names()));
    app.add_option("--script", script_path, "Shots for --strategy scripted (JSON lines)");
    app.add_option("--seed", strategy_options.seed, "Random seed");
    app.add_option("--level", strategy_options.level,
                   "--strategy greedy: execution skill (perfect, hard, medium, easy)")
        ->check(CLI::IsMember({"perfect", "hard", "medium", "easy"}));
    app.add_option("--games", config.games, "Games to play before leaving")
        ->check(CLI::Range(1, 100000));
    app.add_option("--think-ms", think_ms, "Time budget per decision, ms")
        ->check(CLI::Range(0, 60000));
    app.add_option("--timeout", timeout_s, "Give up after this many seconds")
        ->check(CLI::Range(0.1, 864000.0));
    app.add_option("--resume-for", resume_for_s,
                   "After a lost connection, seconds to keep trying to resume the seat (the "
                   "server's --grace plus a margin; 0 = fail at once)")
        ->check(CLI::Range(0.0, 86400.0));
    std::string trace_path;
    app.add_option("--trace", trace_path,
                   "Write a JSON line per shot sent and snapshot received, with the monotonic "
                   "clock in ms (scripts/network_report.py)");
    app.add_option("--log-level", log_level, "trace, debug, info, warn, error, off")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));
    CLI11_PARSE(app, argc, argv);
    // Logs go to stderr: stdout carries only the JSON summary that scripts parse.
    spdlog::set_default_logger(std::make_shared<spdlog::logger>(
        "", std::make_shared<spdlog::sinks::stderr_color_sink_mt>()));
    spdlog::set_level(spdlog::level::from_str(log_level));

    if (!identity_path.empty()) {
        const net::LoadedIdentity identity = net::load_or_create_identity(identity_path);
        if (identity.error) {
            std::cerr << "carrom-bot: " << *identity.error << "\n";
            return 2;
        }
        config.identity = identity.key;
    }
    if (const std::string problem = cli::room_request_problem(room_flags); !problem.empty()) {
        std::cerr << "carrom-bot: " << problem << "\n";
        return 2;
    }
    using Kind = cli::RoomRequestFlags::Kind;
    switch (room_flags.kind) {
    case Kind::Join:
        config.mode = bots::JoinMode::Join;
        break;
    case Kind::Spectate:
        config.mode = bots::JoinMode::Spectate;
        break;
    case Kind::Create:
        config.mode = bots::JoinMode::Create;
        break;
    case Kind::None: // no room flag: a quick match
    case Kind::Quick:
        config.mode = bots::JoinMode::Quick;
        break;
    }
    config.code = room_flags.code;
    config.create.rule_set = room_flags.rule_set;
    config.quick_rule_set = room_flags.rule_set;
    config.create.seats = room_flags.seats;
    config.quick_seats = room_flags.seats;
    if (target_points > 0) {
        config.create.options.target_points = target_points;
    }
    if (boards > 0) {
        config.create.options.boards = boards;
    }
    if (shot_clock_s >= 0.0) {
        config.create.options.shot_clock_s = shot_clock_s;
    }
    config.budget.time = std::chrono::milliseconds(think_ms);
    config.auto_resume = resume_for_s > 0.0;
    config.reconnect.give_up_after_s = resume_for_s;

    if (!script_path.empty()) {
        std::string text;
        if (auto error = read_file(script_path, text)) {
            std::cerr << *error << "\n";
            return 2;
        }
        auto parsed = bots::parse_script(text);
        if (auto* error = std::get_if<std::string>(&parsed)) {
            std::cerr << script_path << ": " << *error << "\n";
            return 2;
        }
        strategy_options.script = std::get<std::vector<Shot>>(std::move(parsed));
    }
    auto made = bots::make_strategy(strategy_options);
    if (auto* error = std::get_if<std::string>(&made)) {
        std::cerr << *error << "\n";
        return 2;
    }
    auto strategy = std::get<std::unique_ptr<bots::Strategy>>(std::move(made));

    bots::TraceWriter trace;
    if (!trace_path.empty()) {
        if (auto error = trace.open(trace_path)) {
            std::cerr << *error << "\n";
            return 2;
        }
    }

    bots::BotRunner runner(config, *strategy);
    std::string announced_room;
    runner.on_message = [&announced_room, &trace](const proto::ServerMessage& message) {
        trace.message(message);
        if (const auto* room = std::get_if<proto::RoomState>(&message)) {
            if (room->code != announced_room) { // for scripts: the code others join with
                announced_room = room->code;
                std::fprintf(stderr, "room %s\n", room->code.c_str());
                std::fflush(stderr);
            }
            spdlog::info("room {} seat {} phase {} turn {}", room->code, room->you,
                         proto::to_string(room->phase), room->turn);
        } else if (const auto* error = std::get_if<proto::Error>(&message)) {
            spdlog::warn("error {}: {}", error->code, error->message);
        }
    };
    runner.on_notice = [&trace](const std::string& text) {
        trace.notice(text);
        spdlog::warn("{}", text);
    };
    runner.on_shoot = [&trace](const proto::Shoot& shoot) { trace.shoot(shoot); };
    runner.start();
    runner.run_until_done(std::chrono::milliseconds(static_cast<std::int64_t>(timeout_s * 1000.0)));
    const auto& summary = runner.summary();
    std::cout << summary_json(summary, *strategy).dump() << std::endl;
    return summary.finished && summary.failure.empty() ? 0 : 1;
}
