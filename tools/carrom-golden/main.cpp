// carrom-golden: the golden cases that the desktop and the browser clients replay
// (tests/golden/README.md).
//   carrom-golden record --url ws://127.0.0.1:PORT --seats 2 --out
//   tests/golden/model/singles.stream.jsonl carrom-golden generate --dir tests/golden
// `record` needs a running carrom-server with bots; `generate` needs no server and no display.

#include "carrom/golden/aim_cases.hpp"
#include "carrom/golden/golden_json.hpp"
#include "carrom/golden/interpolation_cases.hpp"
#include "carrom/golden/model_cases.hpp"
#include "carrom/golden/word_cases.hpp"
#include "stream_recorder.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

namespace {

using carrom::golden::format_case;
using carrom::golden::write_text;
namespace fs = std::filesystem;

bool write_case(const fs::path& path, const nlohmann::json& value) {
    if (!write_text(path.string(), format_case(value))) {
        std::fprintf(stderr, "carrom-golden: cannot write %s\n", path.c_str());
        return false;
    }
    std::printf("wrote %s\n", path.c_str());
    return true;
}

int record(const carrom::golden::RecordOptions& options, const std::string& out) {
    auto recorded = carrom::golden::record_stream(options);
    if (auto* error = std::get_if<std::string>(&recorded)) {
        std::fprintf(stderr, "carrom-golden record: %s\n", error->c_str());
        return 1;
    }
    auto& stream = std::get<std::vector<carrom::golden::StreamLine>>(recorded);
    const double first = stream.empty() ? 0.0 : stream.front().at_s;
    for (auto& line : stream) {
        line.at_s -= first;
    }
    if (!write_text(out, carrom::golden::format_stream(stream))) {
        std::fprintf(stderr, "carrom-golden record: cannot write %s\n", out.c_str());
        return 1;
    }
    std::printf("recorded %zu messages into %s\n", stream.size(), out.c_str());
    return 0;
}

int generate(const fs::path& dir) {
    using namespace carrom::golden;
    bool ok = true;
    for (const char* name : {"singles", "doubles"}) {
        const fs::path stream_path = dir / "model" / (std::string(name) + ".stream.jsonl");
        const auto text = read_text(stream_path.string());
        if (!text) {
            std::fprintf(stderr, "carrom-golden: cannot read %s\n", stream_path.c_str());
            return 1;
        }
        const std::vector<StreamLine> stream = parse_stream(*text);
        ok = write_case(dir / "model" / (std::string(name) + ".json"),
                        {{"about", std::string("The match model after each message of ") +
                                       stream_path.filename().string()},
                         {"stream", stream_path.filename().string()},
                         {"expected", model_steps(stream)}}) &&
             ok;
        if (std::string(name) != "singles") {
            continue;
        }
        // As the replays read it back (times to six decimals).
        const std::vector<StreamLine> cues = parse_stream(format_stream(cue_stream(stream)));
        ok = write_text((dir / "model" / "cues.stream.jsonl").string(), format_stream(cues)) &&
             write_case(dir / "model" / "cues.json",
                        {{"about", "The match model's sound cues at their limits: the first "
                                   "shot of singles.stream.jsonl with 600 events of its own"},
                         {"stream", "cues.stream.jsonl"},
                         {"expected", model_steps(cues)}}) &&
             ok;
        for (const bool every_change : {true, false}) {
            const nlohmann::json input = interpolation_input(stream, 2, every_change);
            ok = write_case(dir / "interpolation" /
                                (every_change ? "every_change.json" : "regular.json"),
                            {{"about", "The interpolation buffer's board at given times, from the "
                                       "first two shots of singles.stream.jsonl"},
                             {"input", input},
                             {"expected", replay_interpolation(input)}}) &&
                 ok;
        }
        const nlohmann::json playout = playout_input(stream, 3);
        ok = write_case(dir / "interpolation" / "playout.json",
                        {{"about", "The playout clock's render times for the snapshots' arrivals "
                                   "of the first three shots of singles.stream.jsonl"},
                         {"input", playout},
                         {"expected", replay_playout(playout)}}) &&
             ok;
    }
    for (const char* side : {"bottom", "right", "top", "left"}) {
        const nlohmann::json input = aim_input(side);
        ok = write_case(dir / "aim" / (std::string(side) + ".json"),
                        {{"about", std::string("Aim gestures in window px on the view of the seat "
                                               "on the ") +
                                       side + " side"},
                         {"input", input},
                         {"expected", replay_aim(input)}}) &&
             ok;
    }
    const nlohmann::json words = words_input();
    ok = write_case(dir / "words" / "words.json", {{"about", "Plain words both clients say"},
                                                   {"input", words},
                                                   {"expected", replay_words(words)}}) &&
         ok;
    return ok ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"carrom-golden: the golden cases of the desktop and browser clients"};
    app.require_subcommand(1);
    carrom::golden::RecordOptions options;
    std::string out;
    auto* rec = app.add_subcommand("record", "Record a match's messages from a running server");
    rec->add_option("--url", options.url, "Server address, ws://HOST:PORT");
    rec->add_option("--seats", options.seats, "2 (singles) or 4 (doubles)")
        ->check(CLI::IsMember({2, 4}));
    rec->add_option("--boards", options.boards, "Boards of the match")->check(CLI::Range(1, 99));
    rec->add_option("--seed", options.seed, "The recording bot's random seed");
    rec->add_option("--strategy", options.strategy, "The recording bot's strategy")
        ->check(CLI::IsMember({"fouls", "random", "greedy"}));
    rec->add_option("--level", options.level, "The server's bots' skill")
        ->check(CLI::IsMember({"easy", "medium", "hard"}));
    rec->add_option("--timeout", options.timeout_s, "Give up after this many seconds");
    rec->add_option("--out", out, "The stream file to write")->required();
    std::string dir = "tests/golden";
    auto* gen = app.add_subcommand("generate", "Write every case's expected output");
    gen->add_option("--dir", dir, "The golden folder (its model/*.stream.jsonl are read)");
    CLI11_PARSE(app, argc, argv);
    if (rec->parsed()) {
        return record(options, out);
    }
    return generate(dir);
}
