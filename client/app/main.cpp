// carrom-client: the SFML desktop client. See docs/client.md.

// GCC 12 at -O2 reports a false "potential null pointer dereference" inside CLI11 2.1.2's
// CLI::detail::split (a std::vector<std::string> growing), inlined into this file. Only this
// translation unit, which holds nothing but flag parsing, turns that one warning off.
#pragma GCC diagnostic ignored "-Wnull-dereference"

#include "app.hpp"
#include "network_link.hpp"
#include "replay_source.hpp"
#include "replay_view.hpp"

#include "carrom/cli/room_request_flags.hpp"
#include "carrom/net/identity_file.hpp"
#include "carrom/proto/types.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
    using carrom::client::RoomRequest;
    carrom::client::app::AppOptions options;
    CLI::App cli{"carrom-client: play carrom against another player over the network"};
    bool bot = false;
    cli.add_option("--url", options.url, "Server address, ws://HOST:PORT or wss://HOST:PORT")
        ->capture_default_str();
    cli.add_option("--ca-file", options.ca_file,
                   "wss://: trust the certificate authorities in this PEM file too");
    cli.add_option("--name", options.name,
                   "Your name (1 to 24 letters; accented letters count twice)")
        ->capture_default_str();
    std::string identity_path = carrom::net::default_identity_path();
    cli.add_option("--identity", identity_path,
                   "Your player key's file, created with a new key when absent; 'none': play as "
                   "a guest (docs/ratings.md)")
        ->capture_default_str();
    carrom::cli::RoomRequestFlags room_flags;
    const carrom::cli::RoomRequestOptions room_opts =
        carrom::cli::add_room_request_flags(cli, room_flags);
    std::string vs_bot;
    auto* bot_flag = cli.add_flag("--bot", bot, "With --create: a server bot takes the other seat");
    auto* vs_bot_opt = cli.add_option(
        "--vs-bot", vs_bot,
        "Create a room where a server bot of this level (random, easy, medium, hard) takes the "
        "other seat (with --seats 4: server bots take the three other seats)");
    vs_bot_opt->excludes(room_opts.join)
        ->excludes(room_opts.spectate)
        ->excludes(room_opts.quick)
        ->excludes(bot_flag);
    std::vector<int> bot_seats;
    auto* bot_seats_opt =
        cli.add_option("--bot-seats", bot_seats,
                       "Doubles with --bot or --vs-bot: the seats the server's bots take, e.g. 2 "
                       "(a bot partner; two players join) or 1,3 (default: 1,2,3)")
            ->delimiter(',');
    bot_seats_opt->excludes(room_opts.join)
        ->excludes(room_opts.spectate)
        ->excludes(room_opts.quick);
    cli.add_flag("--demo", options.demo, "Offline demo: a local stand-in server, no network");
    cli.add_option("--demo-break-at", options.demo_break_at_s,
                   "Demo: seconds before the opponent breaks")
        ->capture_default_str();
    cli.add_option("--demo-autoplay", options.demo_autoplay_s,
                   "Demo: play your shots for you after this many seconds (negative: never)")
        ->capture_default_str();
    cli.add_flag("--mute", options.mute, "No sound");
    cli.add_option("--msaa", options.msaa, "Antialiasing samples for the window (0 = off)")
        ->capture_default_str()
        ->check(CLI::Range(0u, 16u));
    cli.add_option("--width", options.width, "Window width, px")
        ->capture_default_str()
        ->check(CLI::Range(200u, 8192u));
    cli.add_option("--height", options.height, "Window height, px")
        ->capture_default_str()
        ->check(CLI::Range(200u, 8192u));
    cli.add_option("--screenshot", options.screenshot_path,
                   "Render --frames frames (at a fixed 1/60 s step), save the window as PNG, exit");
    cli.add_option("--frames", options.frames, "Frames to render before --screenshot")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    cli.add_option("--after-shots", options.after_shots,
                   "With --screenshot: also wait for this many shots to be played and at rest")
        ->check(CLI::Range(0, 1000));
    cli.add_flag("--board-summary", options.board_summary_shot,
                 "With --screenshot: wait for the card between two boards, then save it");
    cli.add_flag("--game-over", options.game_over_shot,
                 "With --screenshot: wait for the game-over panel, then save it");
    cli.add_option("--report", options.report_path,
                   "With --screenshot: write what the picture shows (room, turn, pieces) as JSON");
    cli.add_option("--timeout", options.timeout_s,
                   "Exit with code 3 if still running after this many seconds (0 = never)")
        ->check(CLI::Range(0.0, 1e6));
    cli.add_option("--bench-frames", options.bench_frames,
                   "Render this many frames of the demo break and print frame times as JSON")
        ->check(CLI::Range(1, 1000000));
    std::string autoplay;
    cli.add_option("--autoplay", autoplay,
                   "Play your turns unattended with the server bots' strategy at this level "
                   "(random, easy, medium, hard), through the mouse input a player uses");
    cli.add_option("--final-state", options.final_state_path,
                   "When the game is over and drawn at rest, write its final state (room, "
                   "winner, reason, scores, pieces) as JSON to this file and exit");
    cli.add_option("--frame-log", options.frame_log_path,
                   "Write each frame drawn in a room (positions, shot time, playout state) and "
                   "each shot sent as JSON lines to this file (docs/client.md)");
    cli.add_option("--settings", options.settings_path,
                   "The settings file (volume, mute, reduced motion; default "
                   "$XDG_CONFIG_HOME/carrom/settings.json)");
    cli.add_option("--input", options.input_script,
                   "Keys and clicks to give the window unattended, e.g. l,Escape or bar:3,dialog:0 "
                   "(docs/client.md)")
        ->delimiter(',');
    std::string replay;
    auto* replay_opt = cli.add_option(
        "--replay", replay,
        "Play back a match journal: http://HOST:PORT/matches/ID, a file, or - for stdin");
    replay_opt->excludes(room_opts.create)
        ->excludes(room_opts.join)
        ->excludes(room_opts.spectate)
        ->excludes(room_opts.quick)
        ->excludes(vs_bot_opt);
    cli.add_option("--replay-speed", options.replay_speed, "Replay speed, 0.25 to 4")
        ->capture_default_str()
        ->check(CLI::Range(0.25, 4.0));
    cli.add_option("--replay-at", options.replay_at_s,
                   "Start the replay paused at this replay time, seconds")
        ->check(CLI::Range(0.0, 1e9));
    CLI11_PARSE(cli, argc, argv);

    if (!replay.empty()) {
        auto loaded = carrom::client::app::load_replay(replay);
        if (auto* problem = std::get_if<std::string>(&loaded)) {
            std::cerr << "carrom-client: " << *problem << "\n";
            return 2;
        }
        auto& model = std::get<carrom::client::ReplayModel>(loaded);
        if (model.mismatches() > 0) {
            std::cerr << "carrom-client: warning: " << model.mismatches()
                      << " input(s) of the journal replay to another state than it recorded\n";
        }
        return carrom::client::app::run_replay(options, std::move(model));
    }

    if (!carrom::proto::is_player_name(options.name)) {
        std::cerr << "carrom-client: --name: type a name of 1 to 24 letters (accented letters "
                     "count twice), not only spaces\n";
        return 2;
    }
    if (const std::string problem = carrom::cli::room_request_problem(room_flags);
        !problem.empty()) {
        std::cerr << "carrom-client: " << problem << "\n";
        return 2;
    }
    if (!options.demo && options.bench_frames == 0 && identity_path != "none" &&
        !identity_path.empty()) {
        const carrom::net::LoadedIdentity identity =
            carrom::net::load_or_create_identity(identity_path);
        if (identity.error) {
            std::cerr << "carrom-client: " << *identity.error << "\n";
            return 2;
        }
        options.identity = identity.key;
    }
    if (options.bench_frames > 0) {
        options.demo = true;
        options.demo_break_at_s = 0.2;
        options.width = options.width == 900 ? 900 : options.width;
    }
    if (!options.demo) {
        if (const std::string problem = carrom::client::app::check_url(options.url);
            !problem.empty()) {
            std::cerr << "carrom-client: " << problem << "\n";
            return 2;
        }
    }
    carrom::proto::BotLevel bot_level = carrom::proto::BotLevel::Medium;
    if (!vs_bot.empty() && !carrom::proto::parse(vs_bot, bot_level)) {
        std::cerr << "carrom-client: --vs-bot must be random, easy, medium or hard\n";
        return 2;
    }
    if (!autoplay.empty()) {
        carrom::proto::BotLevel level{};
        if (!carrom::proto::parse(autoplay, level)) {
            std::cerr << "carrom-client: --autoplay must be random, easy, medium or hard\n";
            return 2;
        }
        options.autoplay = level;
    }
    if (!bot_seats.empty() && !bot && vs_bot.empty()) {
        std::cerr << "carrom-client: --bot-seats needs --bot or --vs-bot\n";
        return 2;
    }
    if (options.demo && room_flags.seats != 2) {
        std::cerr << "carrom-client: the demo is singles (no --seats 4)\n";
        return 2;
    }
    using Kind = carrom::cli::RoomRequestFlags::Kind;
    RoomRequest request;
    request.rule_set = room_flags.rule_set;
    request.seats = room_flags.seats;
    if (room_flags.kind == Kind::Create || options.demo || !vs_bot.empty()) {
        request.kind = RoomRequest::Kind::Create;
        if (bot || !vs_bot.empty()) {
            carrom::proto::BotSeat bot_seat;
            bot_seat.level = bot_level;
            bot_seat.seats = bot_seats;
            request.bot = bot_seat;
        }
        if (const std::string problem = carrom::client::check_room_request(request);
            !problem.empty()) {
            std::cerr << "carrom-client: " << problem << "\n";
            return 2;
        }
        options.request = request;
    } else if (room_flags.kind == Kind::Join) {
        request.kind = RoomRequest::Kind::Join;
        request.code = room_flags.code;
        options.request = request;
    } else if (room_flags.kind == Kind::Spectate) {
        request.kind = RoomRequest::Kind::Spectate;
        request.code = room_flags.code;
        options.request = request;
    } else if (room_flags.kind == Kind::Quick) {
        request.kind = RoomRequest::Kind::Quick;
        options.request = request;
    }
    return carrom::client::app::run_app(options);
}
