#include "store/postgres_directory.hpp"

#include "store/postgres_database.hpp"

#include "carrom/proto/limits.hpp"
#include "carrom/ratings/rating_window.hpp"
#include "store/sha256.hpp"

#include <pqxx/pqxx>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace carrom::store::postgres {
namespace {

// Codes kept reserved for the next rooms; refilled below kPoolLow, kPoolSize at a time.
constexpr std::size_t kPoolSize = 64;
constexpr std::size_t kPoolLow = 48;
// Requests waiting for the thread, at most; more are answered store_busy at once.
constexpr std::size_t kMaxJobs = 4096;
constexpr auto kTick = std::chrono::milliseconds(200);
constexpr auto kCleanUpEvery = std::chrono::seconds(5);

// A code's room is gone with its instance: the instance's lease expired over a minute ago and no
// unfinished match has the code (those move with their takeover).
constexpr const char* kDeadRoomCondition =
    "NOT EXISTS (SELECT 1 FROM instances i WHERE i.id = r.instance_id AND "
    "i.lease_expires > now() - interval '1 minute') AND NOT EXISTS (SELECT 1 FROM matches m "
    "WHERE m.room_code = r.code AND m.finished_ms IS NULL)";

StoreError busy() {
    return StoreError{"store_busy", "the cluster directory has too many requests waiting"};
}

// quick_enqueue's partner for request (of instance_id, whose ticket has waited waited_s) among
// the other live instances' tickets, locked (FOR UPDATE): its ticket, or 0.
std::int64_t find_partner(pqxx::work& t, const QuickRequest& request,
                          const std::string& instance_id, double waited_s) {
    if (!request.rated) {
        // The oldest guest's ticket of a live instance for the same rule set.
        const pqxx::result r = t.exec_params(
            "SELECT q.ticket FROM quick_tickets q JOIN instances i ON i.id = q.instance_id WHERE "
            "q.rule_set = $1 AND q.instance_id <> $2 AND q.room_code IS NULL AND q.rating IS "
            "NULL AND i.lease_expires > now() ORDER BY q.since, q.ticket LIMIT 1 FOR UPDATE OF q "
            "SKIP LOCKED",
            request.rule_set, instance_id);
        return r.empty() ? 0 : r[0][0].as<std::int64_t>();
    }
    // Rated: the closest rating within the acceptable gap of the longer wait, then the oldest.
    const pqxx::result r = t.exec_params(
        "SELECT q.ticket, q.rating, extract(epoch FROM now() - q.since)::float8 FROM "
        "quick_tickets q JOIN instances i ON i.id = q.instance_id WHERE q.rule_set = $1 AND "
        "q.instance_id <> $2 AND q.room_code IS NULL AND q.rating IS NOT NULL AND q.key_sha256 "
        "<> decode($3, 'hex') AND i.lease_expires > now() ORDER BY q.since, q.ticket FOR UPDATE "
        "OF q SKIP LOCKED",
        request.rule_set, instance_id, to_hex(request.rated->key_hash));
    std::int64_t best = 0;
    double best_gap = 0.0;
    for (const auto& row : r) {
        const double gap = std::abs(row[1].as<double>() - request.rated->rating);
        const double acceptable = ratings::acceptable_gap(std::max(waited_s, row[2].as<double>()));
        if (gap <= acceptable && (best == 0 || gap < best_gap)) {
            best = row[0].as<std::int64_t>();
            best_gap = gap;
        }
    }
    return best;
}

} // namespace

PostgresDirectory::PostgresDirectory(std::string url, std::string shown, std::string instance_id,
                                     std::string public_url)
    : url_(std::move(url)), shown_(std::move(shown)), instance_id_(std::move(instance_id)),
      public_url_(std::move(public_url)), random_(std::random_device{}()) {}

PostgresDirectory::~PostgresDirectory() {
    stop();
}

pqxx::connection& PostgresDirectory::connection() {
    if (!connection_ || !connection_->is_open()) {
        connection_.reset();
        connection_ = connect(url_);
    }
    return *connection_;
}

std::string PostgresDirectory::random_code() {
    std::string code;
    constexpr std::size_t kLetters = sizeof proto::kRoomCodeAlphabet - 1;
    for (std::size_t i = 0; i < proto::kRoomCodeLength; ++i) {
        code.push_back(proto::kRoomCodeAlphabet[random_() % kLetters]);
    }
    return code;
}

void PostgresDirectory::open() {
    try {
        pqxx::work t(connection());
        t.exec_params(std::string("DELETE FROM rooms r WHERE r.instance_id = $1 AND NOT EXISTS "
                                  "(SELECT 1 FROM matches m WHERE m.room_code = r.code AND "
                                  "m.finished_ms IS NULL)"),
                      instance_id_);
        t.exec_params("DELETE FROM quick_tickets WHERE instance_id = $1", instance_id_);
        t.commit();
        refill_pool(connection());
    } catch (const std::exception& e) {
        connection_.reset();
        spdlog::warn("cluster: room codes not reserved at start (reserved when the database "
                     "answers): {}",
                     e.what());
    }
}

void PostgresDirectory::start(std::function<void(std::vector<QuickPairing>)> on_paired) {
    on_paired_ = std::move(on_paired);
    thread_ = std::thread([this] { run(); });
}

void PostgresDirectory::stop() {
    {
        const std::lock_guard lock(mutex_);
        if (stopping_ && !thread_.joinable()) {
            return;
        }
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) {
        thread_.join();
    }
    std::deque<Job> left;
    {
        const std::lock_guard lock(mutex_);
        left.swap(jobs_);
    }
    const StoreError stopped{"store_stopped", "the server is stopping"};
    for (Job& job : left) {
        job(nullptr, stopped);
    }
}

template <class T>
void PostgresDirectory::ask(Answer<T> done, std::function<void(pqxx::connection&, T&)> fill) {
    // An exception from fill: run() calls the job again without a connection, with the error.
    post([done = std::move(done), fill = std::move(fill)](pqxx::connection* c,
                                                          const std::optional<StoreError>& error) {
        Loaded<T> out;
        if (c == nullptr) {
            out.error = error;
        } else {
            fill(*c, out.value);
        }
        done(std::move(out));
    });
}

void PostgresDirectory::post(Job job) {
    {
        std::unique_lock lock(mutex_);
        if (!stopping_ && jobs_.size() < kMaxJobs) {
            jobs_.push_back(std::move(job));
            lock.unlock();
            wake_.notify_one();
            return;
        }
    }
    job(nullptr, busy());
}

void PostgresDirectory::run() {
    std::unique_lock lock(mutex_);
    auto next_tick = std::chrono::steady_clock::now();
    while (!stopping_) {
        if (jobs_.empty()) {
            wake_.wait_until(lock, next_tick,
                             [this] { return stopping_ || !jobs_.empty() || refill_wanted_; });
        }
        if (refill_wanted_) {
            refill_wanted_ = false;
            next_tick = std::chrono::steady_clock::now(); // maintain now
        }
        if (stopping_) {
            break;
        }
        if (!jobs_.empty() && std::chrono::steady_clock::now() < next_tick) {
            Job job = std::move(jobs_.front());
            jobs_.pop_front();
            lock.unlock();
            try {
                job(&connection(), std::nullopt);
            } catch (const std::exception& e) {
                connection_.reset();
                job(nullptr, error_from(e, shown_, "asking the cluster directory on"));
            }
            lock.lock();
            continue;
        }
        lock.unlock();
        maintain();
        next_tick = std::chrono::steady_clock::now() + kTick;
        lock.lock();
    }
}

void PostgresDirectory::maintain() {
    try {
        refill_pool(connection());
        fetch_pairings(connection());
        const auto now = std::chrono::steady_clock::now();
        if (now >= next_clean_up_) {
            next_clean_up_ = now + kCleanUpEvery;
            clean_up(connection());
        }
    } catch (const std::exception& e) {
        connection_.reset(); // the next tick tries again; the cluster thread logs the outage
        spdlog::debug("cluster directory: {}", e.what());
    }
}

void PostgresDirectory::refill_pool(pqxx::connection& c) {
    {
        const std::lock_guard lock(mutex_);
        if (pool_.size() >= kPoolLow) {
            return;
        }
    }
    std::vector<std::string> codes;
    for (std::size_t i = 0; i < kPoolSize; ++i) {
        codes.push_back(random_code());
    }
    pqxx::work t(c);
    const pqxx::result reserved =
        t.exec_params("INSERT INTO rooms (code, instance_id) SELECT unnest($1::text[]), $2 "
                      "ON CONFLICT (code) DO NOTHING RETURNING code",
                      text_array(codes), instance_id_);
    t.commit();
    const std::lock_guard lock(mutex_);
    for (const auto& row : reserved) {
        pool_.push_back(row[0].as<std::string>());
    }
}

void PostgresDirectory::fetch_pairings(pqxx::connection& c) {
    {
        const std::lock_guard lock(mutex_);
        if (tickets_waiting_ == 0) {
            return;
        }
    }
    pqxx::work t(c);
    const pqxx::result paired =
        t.exec_params("DELETE FROM quick_tickets WHERE instance_id = $1 AND room_code IS NOT NULL "
                      "RETURNING ticket, room_code, room_url",
                      instance_id_);
    t.commit();
    if (paired.empty()) {
        return;
    }
    std::vector<QuickPairing> out;
    for (const auto& row : paired) {
        out.push_back(QuickPairing{row[0].as<std::int64_t>(), row[1].as<std::string>(),
                                   row[2].as<std::string>()});
    }
    {
        const std::lock_guard lock(mutex_);
        tickets_waiting_ -= std::min(tickets_waiting_, out.size());
    }
    if (on_paired_) {
        on_paired_(std::move(out));
    }
}

void PostgresDirectory::clean_up(pqxx::connection& c) {
    pqxx::work t(c);
    t.exec(std::string("DELETE FROM rooms r WHERE ") + kDeadRoomCondition);
    t.exec("DELETE FROM quick_tickets q WHERE NOT EXISTS (SELECT 1 FROM instances i WHERE "
           "i.id = q.instance_id AND i.lease_expires > now())");
    t.commit();
}

std::optional<std::string> PostgresDirectory::take_room_code() {
    const std::lock_guard lock(mutex_);
    if (pool_.empty()) {
        return std::nullopt;
    }
    std::string code = std::move(pool_.back());
    pool_.pop_back();
    if (pool_.size() < kPoolLow && !refill_wanted_) {
        refill_wanted_ = true;
        wake_.notify_one(); // refill now rather than at the next tick
    }
    return code;
}

void PostgresDirectory::release_room_code(const std::string& code) {
    post([this, code](pqxx::connection* c, const std::optional<StoreError>& error) {
        if (c == nullptr) {
            spdlog::debug("cluster: room code {} not freed ({}): freed when the instance's "
                          "codes are next cleaned up",
                          code, error ? error->message : "");
            return;
        }
        pqxx::work t(*c);
        t.exec_params("DELETE FROM rooms WHERE code = $1 AND instance_id = $2", code, instance_id_);
        t.commit();
    });
}

void PostgresDirectory::locate_room(std::string code, Answer<RoomLocation> done) {
    ask<RoomLocation>(std::move(done), [this, code = std::move(code)](pqxx::connection& c,
                                                                      RoomLocation& out) {
        pqxx::read_transaction t(c);
        const pqxx::result r = t.exec_params(
            "SELECT r.instance_id, coalesce(i.public_url, ''), coalesce(i.lease_expires > now(), "
            "false), EXISTS (SELECT 1 FROM matches m WHERE m.room_code = r.code AND "
            "m.finished_ms IS NULL) FROM rooms r LEFT JOIN instances i ON i.id = r.instance_id "
            "WHERE r.code = $1",
            code);
        t.commit();
        out.room_code = code;
        if (!r.empty()) {
            const std::string owner = r[0][0].as<std::string>();
            const bool alive = r[0][2].as<bool>();
            const bool running = r[0][3].as<bool>();
            out.instance_id = owner;
            if (owner != instance_id_ && alive) {
                out.where = RoomLocation::Where::Elsewhere;
                out.public_url = r[0][1].as<std::string>();
            } else if (running) {
                out.where = RoomLocation::Where::Moving;
            }
        }
    });
}

void PostgresDirectory::locate_seat(TokenHash token, Answer<RoomLocation> done) {
    ask<RoomLocation>(std::move(done), [this, token](pqxx::connection& c, RoomLocation& out) {
        pqxx::read_transaction t(c);
        // The seat's latest match: unfinished, or finished in a room still open (its code not
        // reserved again since the match began), where the seat is held for a rematch.
        const pqxx::result r = t.exec_params(
            "SELECT m.room_code, coalesce(r.instance_id, m.owner_instance, ''), "
            "coalesce(i.public_url, ''), coalesce(i.lease_expires > now(), false), "
            "m.handed_over, m.finished_ms IS NULL, r.code IS NOT NULL, m.id FROM seat_tokens s "
            "JOIN matches m ON m.id = s.match_id LEFT JOIN rooms r ON r.code = m.room_code AND "
            "r.reserved_at <= to_timestamp(m.created_ms / 1000.0) LEFT JOIN instances i ON "
            "i.id = coalesce(r.instance_id, m.owner_instance) WHERE s.token_sha256 = "
            "decode($1, 'hex') ORDER BY m.created_ms DESC LIMIT 1",
            to_hex(token));
        t.commit();
        if (!r.empty()) {
            out.room_code = r[0][0].as<std::string>();
            out.instance_id = r[0][1].as<std::string>();
            const bool alive = r[0][3].as<bool>();
            const bool unfinished = r[0][5].as<bool>();
            const bool room_open = r[0][6].as<bool>();
            if ((unfinished || room_open) && out.instance_id != instance_id_ && alive &&
                !r[0][4].as<bool>()) {
                out.where = RoomLocation::Where::Elsewhere;
                out.public_url = r[0][2].as<std::string>();
            } else if (unfinished) {
                out.where = RoomLocation::Where::Moving;
            } else if (!room_open || !alive) {
                out.finished_match = r[0][7].as<std::string>();
            }
        }
    });
}

void PostgresDirectory::quick_enqueue(QuickRequest request, Answer<QuickEnqueued> done) {
    ask<QuickEnqueued>(std::move(done), [this, request = std::move(request)](pqxx::connection& c,
                                                                             QuickEnqueued& out) {
        std::optional<std::string> code = take_room_code();
        const auto unused_code = [&] {
            if (code) {
                const std::lock_guard lock(mutex_);
                pool_.push_back(std::move(*code)); // not used: still reserved for this instance
            }
        };
        pqxx::work t(c);
        double waited_s = 0.0;
        if (request.ticket != 0) {
            // Asked again: the player's ticket, if it still waits (else paired or withdrawn).
            const pqxx::result mine = t.exec_params(
                "SELECT extract(epoch FROM now() - since)::float8 FROM quick_tickets WHERE ticket "
                "= $1 AND instance_id = $2 AND room_code IS NULL FOR UPDATE",
                request.ticket, instance_id_);
            if (mine.empty()) {
                t.commit();
                unused_code();
                out = QuickEnqueued{false, request.ticket, {}};
                return;
            }
            waited_s = mine[0][0].as<double>();
        }
        const std::int64_t partner = code ? find_partner(t, request, instance_id_, waited_s) : 0;
        if (partner != 0) {
            t.exec_params(
                "UPDATE quick_tickets SET room_code = $2, room_url = $3 WHERE ticket = $1", partner,
                *code, public_url_);
            if (request.ticket != 0) {
                t.exec_params("DELETE FROM quick_tickets WHERE ticket = $1", request.ticket);
            }
            t.commit();
            if (request.ticket != 0) {
                const std::lock_guard lock(mutex_);
                tickets_waiting_ -= std::min<std::size_t>(tickets_waiting_, 1);
            }
            out = QuickEnqueued{true, partner, *code};
            return;
        }
        if (request.ticket != 0) {
            t.commit();
            unused_code();
            out = QuickEnqueued{false, request.ticket, {}};
            return;
        }
        const std::optional<double> rating =
            request.rated ? std::optional(request.rated->rating) : std::nullopt;
        const std::optional<std::string> key =
            request.rated ? std::optional(to_hex(request.rated->key_hash)) : std::nullopt;
        const pqxx::result mine =
            t.exec_params("INSERT INTO quick_tickets (instance_id, rule_set, rating, key_sha256) "
                          "VALUES ($1, $2, $3, decode($4, 'hex')) RETURNING ticket",
                          instance_id_, request.rule_set, rating, key);
        t.commit();
        unused_code();
        {
            const std::lock_guard lock(mutex_);
            ++tickets_waiting_;
        }
        out = QuickEnqueued{false, mine[0][0].as<std::int64_t>(), {}};
    });
}

void PostgresDirectory::quick_withdraw(std::int64_t ticket, Answer<bool> done) {
    ask<bool>(std::move(done), [this, ticket](pqxx::connection& c, bool& out) {
        pqxx::work t(c);
        const pqxx::result r = t.exec_params(
            "DELETE FROM quick_tickets WHERE ticket = $1 AND instance_id = $2 AND room_code IS "
            "NULL RETURNING ticket",
            ticket, instance_id_);
        t.commit();
        out = !r.empty();
        if (out) {
            const std::lock_guard lock(mutex_);
            tickets_waiting_ -= std::min<std::size_t>(tickets_waiting_, 1);
        }
    });
}

} // namespace carrom::store::postgres
