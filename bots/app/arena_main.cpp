// carrom-arena: plays --games offline games between two strategies (rules + exact physics, no
// network) and prints one JSON object: wins, draws, a 95 % interval of A's win rate, strokes per
// game and per side, fouls, and the candidates per second each search strategy simulated.
// Games alternate seats (A breaks in even games). With --seats 4 (doubles) A plays a team of two
// (seats 0 and 2, or 1 and 3) against B's, one strategy object per seat. Deterministic for a
// seed when no time budget ends a search (give --candidates and a generous --think-ms).
#include "carrom/bots/arena.hpp"
#include "carrom/bots/strategy.hpp"
#include "carrom/proto/types.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace {

using namespace carrom;

// "random", "sampling", "greedy" (hard) or "greedy:LEVEL".
bots::StrategyOptions parse_spec(const std::string& spec, std::uint64_t seed) {
    bots::StrategyOptions options;
    const auto colon = spec.find(':');
    options.name = spec.substr(0, colon);
    if (colon != std::string::npos) {
        options.level = spec.substr(colon + 1);
    }
    options.seed = seed;
    return options;
}

std::unique_ptr<bots::Strategy> make(const std::string& spec, std::uint64_t seed) {
    auto made = bots::make_strategy(parse_spec(spec, seed));
    if (auto* error = std::get_if<std::string>(&made)) {
        std::cerr << spec << ": " << *error << "\n";
        std::exit(2);
    }
    return std::get<std::unique_ptr<bots::Strategy>>(std::move(made));
}

// Wilson score interval for a proportion, 95 %.
std::pair<double, double> wilson(double successes, double trials) {
    if (trials <= 0.0) {
        return {0.0, 1.0};
    }
    constexpr double z = 1.959964;
    const double p = successes / trials;
    const double denominator = 1.0 + z * z / trials;
    const double centre = (p + z * z / (2.0 * trials)) / denominator;
    const double half =
        z * std::sqrt(p * (1.0 - p) / trials + z * z / (4.0 * trials * trials)) / denominator;
    return {centre - half, centre + half};
}

struct Totals {
    int games = 0, a_wins = 0, b_wins = 0, draws = 0, unfinished = 0;
    long strokes = 0, boards = 0;
    std::array<bots::SeatRecord, 2> side{}; // 0: A (both seats in doubles), 1: B
};

void add(bots::SeatRecord& into, const bots::SeatRecord& r) {
    into.strokes += r.strokes;
    into.fouls += r.fouls;
    into.pocketed += r.pocketed;
    into.refusals += r.refusals;
    into.candidates += r.candidates;
    into.think_s += r.think_s;
}

nlohmann::json side_json(const bots::SeatRecord& r, int games) {
    const double g = std::max(games, 1);
    const double strokes = std::max(r.strokes, 1);
    return {
        {"strokes_per_game", r.strokes / g},
        {"fouls_per_stroke", r.fouls / strokes},
        {"pocketed_per_stroke", r.pocketed / strokes},
        {"refusals", r.refusals},
        {"candidates", r.candidates},
        {"think_s", r.think_s},
        {"candidates_per_s", r.think_s > 0.0 ? static_cast<double>(r.candidates) / r.think_s : 0.0},
        {"ms_per_decision", 1000.0 * r.think_s / strokes}};
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"carrom-arena: offline games between two bot strategies"};
    std::string a_spec = "greedy:hard";
    std::string b_spec = "random";
    std::string rule_set_name = "icf";
    int games = 20;
    int jobs = 1;
    int think_ms = 300;
    int candidates = 0;
    int max_strokes = 3000;
    int target_points = 0;
    int seats = 2;
    std::uint64_t seed = 1;
    app.add_option("--a", a_spec,
                   "Strategy A: random, sampling, greedy[:perfect|hard|medium|easy]");
    app.add_option("--b", b_spec, "Strategy B (same forms)");
    app.add_option("--rule-set", rule_set_name, "Rule set")
        ->check(CLI::IsMember({"icf", "seed", "freestyle", "discpool"}));
    app.add_option("--games", games, "Games to play")->check(CLI::Range(1, 100000));
    app.add_option("--jobs", jobs, "Games played at once (threads)")->check(CLI::Range(1, 64));
    app.add_option("--think-ms", think_ms, "Time budget per decision, ms")
        ->check(CLI::Range(1, 600000));
    app.add_option("--candidates", candidates, "Most candidates per decision (0 = no limit)")
        ->check(CLI::Range(0, 100000000));
    app.add_option("--max-strokes", max_strokes, "Strokes after which a game is a draw")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--target-points", target_points, "icf/freestyle target (0 = rule default)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--seats", seats, "2 (singles) or 4 (doubles: A and B each play a team)")
        ->check(CLI::IsMember({2, 4}));
    app.add_option("--seed", seed,
                   "Seed of the strategies (game g uses seed*1000+2g and +1; doubles: the "
                   "partners the same plus 2^32)");
    CLI11_PARSE(app, argc, argv);
    make(a_spec, 1); // exits with status 2 on a bad spec
    make(b_spec, 1);

    rules::RuleSet rule_set = rules::RuleSet::Icf;
    rules::parse_rule_set(rule_set_name, rule_set);
    rules::RulesConfig config;
    config.shot_clock_s = 0.0;
    config.seat_count = seats;
    if (target_points > 0) {
        config.target_points = target_points;
        config.freestyle.target = target_points;
    }
    const rules::MatchState start = rules::new_match(rule_set, config, PhysicsConfig{});
    bots::ArenaOptions options;
    options.budget.time = std::chrono::milliseconds(think_ms);
    if (candidates > 0) {
        options.budget.max_candidates = candidates;
    }
    options.max_strokes = max_strokes;

    Totals totals;
    std::mutex mutex;
    std::atomic<int> next{0};
    const auto started = std::chrono::steady_clock::now();
    auto worker = [&] {
        for (int g = next++; g < games; g = next++) {
            const std::uint64_t game_seed = seed * 1000 + 2 * static_cast<std::uint64_t>(g);
            const int a_team = g % 2; // seat 0 (team 0) breaks the first board
            // One strategy per seat: seat s is A's when its team is a_team; partners (seats
            // 2 and 3 in doubles) get the seeds of seats 0 and 1 plus 2^32.
            std::vector<std::unique_ptr<bots::Strategy>> owned;
            std::vector<bots::Strategy*> players;
            for (int s = 0; s < seats; ++s) {
                const bool is_a = rules::team_of_seat(s, seats) == a_team;
                const std::uint64_t partner = s >= 2 ? (std::uint64_t{1} << 32) : 0;
                owned.push_back(is_a ? make(a_spec, game_seed + partner)
                                     : make(b_spec, game_seed + 1 + partner));
                players.push_back(owned.back().get());
            }
            const bots::GameRecord record = bots::play_game(start, players, options);
            const std::lock_guard lock(mutex);
            ++totals.games;
            totals.boards += record.boards;
            for (int s = 0; s < seats; ++s) {
                const auto& seat_record = record.seats[static_cast<std::size_t>(s)];
                totals.strokes += seat_record.strokes;
                add(totals.side[rules::team_of_seat(s, seats) == a_team ? 0 : 1], seat_record);
            }
            if (!record.finished) {
                ++totals.unfinished;
            } else if (!record.winner_team) {
                ++totals.draws;
            } else if (*record.winner_team == a_team) {
                ++totals.a_wins;
            } else {
                ++totals.b_wins;
            }
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < jobs; ++j) {
        threads.emplace_back(worker);
    }
    for (auto& thread : threads) {
        thread.join();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const auto [lo, hi] = wilson(totals.a_wins, totals.games);
    const double g = std::max(totals.games, 1);
    const nlohmann::json out = {{"a", a_spec},
                                {"b", b_spec},
                                {"rule_set", rule_set_name},
                                {"seats", seats},
                                {"games", totals.games},
                                {"a_wins", totals.a_wins},
                                {"b_wins", totals.b_wins},
                                {"draws", totals.draws},
                                {"unfinished", totals.unfinished},
                                {"a_win_rate", totals.a_wins / g},
                                {"a_win_rate_95", {lo, hi}},
                                {"strokes_per_game", static_cast<double>(totals.strokes) / g},
                                {"boards_per_game", static_cast<double>(totals.boards) / g},
                                {"a_side", side_json(totals.side[0], totals.games)},
                                {"b_side", side_json(totals.side[1], totals.games)},
                                {"think_ms", think_ms},
                                {"candidates_limit", candidates},
                                {"seed", seed},
                                {"jobs", jobs},
                                {"seconds", seconds}};
    std::cout << out.dump() << std::endl;
    return 0;
}
