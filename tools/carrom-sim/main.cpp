// carrom-sim: simulates a scene given as JSON (a file argument or stdin) and prints the result
// as JSON. Bad input prints {"error": {"code", "path", "message"}} on stderr and exits 2.
// See docs/carrom-sim.md.

#include "frame_error_mode.hpp"
#include "replay_mode.hpp"
#include "rules_mode.hpp"
#include "sim_cli.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

using carrom::proto::Error;
using Json = nlohmann::json;

using carrom::sim_cli::kExitBadInput;
constexpr int kExitInternal = 1;

// Text from the command line (paths, flags) may not be UTF-8: replace bad bytes when printing.
std::string dump(const Json& j, int indent = -1) {
    return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

int fail(const Error& error) {
    std::cerr << dump(carrom::proto::error_to_json(error)) << '\n';
    return kExitBadInput;
}

// Reads a little over kMaxSceneBytes at most, so that oversized input is rejected by the
// decoder without reading all of it.
bool read_input(const std::string& path, std::string& text, Error& error) {
    std::ifstream file;
    std::istream* in = &std::cin;
    if (!path.empty() && path != "-") {
        file.open(path, std::ios::binary);
        if (!file) {
            error = {"io_error", "cannot open the scene file '" + path + "'"};
            return false;
        }
        in = &file;
    }
    std::vector<char> chunk(65536);
    while (text.size() <= carrom::proto::kMaxSceneBytes) {
        in->read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const auto got = in->gcount();
        if (got <= 0) {
            break;
        }
        text.append(chunk.data(), static_cast<std::size_t>(got));
    }
    if (in->bad()) {
        error = {"io_error", "reading the scene failed"};
        return false;
    }
    return true;
}

int run_rules(const std::string& path) {
    if (path.empty() || path == "-") {
        return carrom::run_rules_mode(std::cin, std::cout, std::cerr);
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        return fail({"io_error", "cannot open the rules file '" + path + "'"});
    }
    return carrom::run_rules_mode(file, std::cout, std::cerr);
}

int run_replay(const std::string& path, bool pretty) {
    if (path.empty() || path == "-") {
        return carrom::run_replay_mode(std::cin, std::cout, std::cerr, pretty);
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        return fail({"io_error", "cannot open the journal file '" + path + "'"});
    }
    return carrom::run_replay_mode(file, std::cout, std::cerr, pretty);
}

// Everything the command line sets.
struct CliArgs {
    carrom::sim_cli::RunOptions options;
    std::string path;
    double at_s = 0.0;
    bool at_given = false;
    bool pretty = false;
    bool no_events = false;
    bool rules = false;
    bool replay = false;
    std::string frames_path; // --frame-error
};

void add_flags(CLI::App& app, CliArgs& args) {
    using carrom::sim_cli::Integrator;
    const std::map<std::string, Integrator> integrators{{"exact", Integrator::Exact},
                                                        {"fixed", Integrator::Fixed}};
    app.add_option("scene", args.path,
                   "scene (or rules question, or journal) JSON file; '-' or none reads stdin");
    app.add_option("--integrator", args.options.integrator, "exact (default) or fixed")
        ->transform(CLI::CheckedTransformer(integrators, CLI::ignore_case));
    app.add_option("--dt", args.options.frame_dt_s, "fixed: frame time step, s (default 1/60)")
        ->check(CLI::PositiveNumber)
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--substeps", args.options.substeps, "fixed: steps per frame (default 1)")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--at", args.at_s, "print the state at time T, s, instead of the end")
        ->check(CLI::Range(0.0, 1e6));
    app.add_option("--repeat", args.options.repeat,
                   "run N times; report median and minimum wall time")
        ->check(CLI::Range(1, 1000000));
    app.add_flag("--no-events", args.no_events, "leave the event list out");
    app.add_flag("--pretty", args.pretty, "indent the JSON output");
    app.add_flag("--invariants", args.options.invariants,
                 "exact: check overlap, cushions and kinetic energy at every event time");
    auto* rules =
        app.add_flag("--rules", args.rules, "rules mode: read a rules question instead of a scene");
    auto* replay =
        app.add_flag("--replay", args.replay,
                     "replay mode: verify a match journal; exit 1 if an outcome differs");
    replay->excludes(rules);
    app.add_option("--frame-error", args.frames_path,
                   "frame error mode: compare a carrom-client --frame-log FILE with the exact "
                   "trajectories of the journal given as the input")
        ->excludes(rules)
        ->excludes(replay);
}

int simulate(CliArgs& args) {
    args.options.record_events = !args.no_events;
    if (args.at_given) {
        args.options.at_s = args.at_s;
    }
    std::string text;
    Error error;
    if (!read_input(args.path, text, error)) {
        return fail(error);
    }
    const auto scene = carrom::proto::decode_scene_text(text);
    if (!scene.ok()) {
        return fail(*scene.error);
    }
    const auto output = carrom::sim_cli::run_scene(scene.value, args.options);
    if (output.error) {
        return fail(*output.error);
    }
    std::cout << dump(output.document, args.pretty ? 2 : -1) << '\n';
    return 0;
}

int run(int argc, char** argv) {
    CLI::App app{"carrom-sim: simulate a carrom scene given as JSON and print the result as JSON "
                 "(docs/carrom-sim.md)"};
    CliArgs args;
    add_flags(app, args);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail({"bad_argument", e.what()});
    }
    if (!std::isfinite(args.options.frame_dt_s) || !std::isfinite(args.at_s)) {
        return fail({"bad_argument", "--dt and --at must be finite numbers"});
    }
    args.at_given = app.count("--at") > 0;
    if (args.replay) {
        return run_replay(args.path, args.pretty);
    }
    if (!args.frames_path.empty()) {
        return carrom::run_frame_error_mode(args.frames_path, args.path, std::cout, std::cerr,
                                            args.pretty);
    }
    return args.rules ? run_rules(args.path) : simulate(args);
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << dump(carrom::proto::error_to_json({"internal", e.what()})) << '\n';
        return kExitInternal;
    }
}
