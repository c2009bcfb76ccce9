#include "store/postgres_cluster.hpp"

#include "store/postgres_database.hpp"
#include "store/postgres_reader.hpp"

#include <pqxx/pqxx>
#include <spdlog/spdlog.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <random>
#include <stdexcept>

namespace carrom::store::postgres {
namespace {

// The lease's length as an SQL interval expression on parameter $n (milliseconds).
std::string lease_interval(int n) {
    return "($" + std::to_string(n) + "::bigint * interval '1 millisecond')";
}

// Unix milliseconds of a timestamptz expression.
std::string unix_ms(const std::string& timestamp) {
    return "(extract(epoch FROM " + timestamp + ") * 1000)::bigint";
}

// The channel a draining instance notifies once it handed matches over: every instance's
// cluster thread listens and runs its next round at once.
constexpr const char* kWakeChannel = "carrom_cluster_wake";

class WakeReceiver final : public pqxx::notification_receiver {
public:
    WakeReceiver(pqxx::connection_base& c, bool& woken)
        : pqxx::notification_receiver(c, kWakeChannel), woken_(woken) {}
    void operator()(const std::string&, int) override { woken_ = true; }

private:
    bool& woken_;
};

bool take_instance_lock(pqxx::connection& c, const std::string& id) {
    pqxx::nontransaction t(c);
    return t
        .exec_params("SELECT pg_try_advisory_lock($1, hashtext($2))", kInstanceLockClass, id)[0][0]
        .as<bool>();
}

} // namespace

std::optional<StoreError> check_cluster_options(const ClusterOptions& options) {
    const std::string& id = options.instance_id;
    const bool id_ok = !id.empty() && id.size() <= 64 &&
                       id.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                            "0123456789._-") == std::string::npos;
    if (!id_ok) {
        return StoreError{"bad_instance_id", "--instance-id \"" + id +
                                                 "\" is not 1 to 64 characters of "
                                                 "A-Z, a-z, 0-9, '.', '_' and '-'"};
    }
    const std::string& url = options.public_url;
    const std::size_t scheme = url.rfind("ws://", 0) == 0 ? 5 : url.rfind("wss://", 0) == 0 ? 6 : 0;
    bool url_ok = scheme != 0 && url.size() > scheme && url.size() <= 2000 && url[scheme] != '/' &&
                  url[scheme] != ':';
    for (const char c : url) {
        url_ok = url_ok && static_cast<unsigned char>(c) > 0x20 && c != 0x7f && c != '"' &&
                 c != '\'' && c != '\\';
    }
    if (!url_ok) {
        return StoreError{"bad_public_url",
                          "--public-url \"" + url.substr(0, 200) +
                              "\" is not a ws:// or wss:// URL with a host (the address clients "
                              "reach this instance at)"};
    }
    if (options.lease < std::chrono::milliseconds(500) ||
        options.lease > std::chrono::minutes(10)) {
        return StoreError{"bad_lease", "--lease must be 0.5 to 600 seconds"};
    }
    return std::nullopt;
}

std::string generate_instance_id() {
    char host[256] = {};
    (void)::gethostname(host, sizeof host - 1);
    std::string id;
    for (const char* c = host; *c != '\0' && id.size() < 40; ++c) {
        if (std::isalnum(static_cast<unsigned char>(*c)) != 0 || *c == '.' || *c == '-') {
            id.push_back(*c);
        }
    }
    static constexpr char kDigits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
    std::random_device random;
    id += id.empty() ? "" : "-";
    for (int i = 0; i < 6; ++i) {
        id.push_back(kDigits[random() % 36]);
    }
    return id;
}

PostgresCluster::PostgresCluster(std::string url, std::string shown, ClusterOptions options,
                                 std::shared_ptr<MatchOwnership> ownership)
    : url_(std::move(url)), shown_(std::move(shown)), options_(std::move(options)),
      directory_(url_, shown_, options_.instance_id, options_.public_url),
      ownership_(std::move(ownership)) {}

PostgresCluster::~PostgresCluster() {
    stop();
}

std::optional<StoreError> PostgresCluster::open() {
    try {
        connection_ = connect(url_);
        // A process of the same id that just died (kill -9) holds the lock until PostgreSQL
        // has ended its session: a moment.
        bool locked = take_instance_lock(*connection_, options_.instance_id);
        for (int i = 0; i < 30 && !locked; ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            locked = take_instance_lock(*connection_, options_.instance_id);
        }
        if (!locked) {
            connection_.reset();
            return StoreError{"cluster_instance_in_use",
                              "instance id " + options_.instance_id + " is running already on " +
                                  shown_ + " (another live carrom-server has it)"};
        }
        pqxx::work t(*connection_);
        write_lease(t, true);
        t.commit();
        lease_ok_ = true;
        registered_ = true;
    } catch (const std::exception& e) {
        connection_.reset();
        return error_from(e, shown_, "registering the instance on");
    }
    directory_.open();
    return std::nullopt;
}

void PostgresCluster::drop_connection() {
    wake_receiver_.reset();
    connection_.reset();
}

pqxx::connection& PostgresCluster::connection() {
    if (connection_ && connection_->is_open()) {
        return *connection_;
    }
    drop_connection();
    auto c = connect(url_);
    if (!take_instance_lock(*c, options_.instance_id)) {
        throw std::runtime_error("instance id " + options_.instance_id +
                                 " is held by another live carrom-server");
    }
    connection_ = std::move(c);
    return *connection_;
}

Loaded<std::vector<RecoveredMatch>> PostgresCluster::claim(bool mine_too) {
    Loaded<std::vector<RecoveredMatch>> out;
    try {
        pqxx::work t(connection());
        // Rows another claimer or a writer holds are skipped (the next scan sees them again);
        // the epoch condition makes a claim of a row that changed meanwhile update nothing.
        // Also the matches a draining instance handed to this one (handed_over).
        const pqxx::result claimed = t.exec_params(
            "UPDATE matches m SET owner_instance = $1, owner_epoch = m.owner_epoch + 1, "
            "handed_over = false FROM ("
            "SELECT x.id, x.owner_epoch, x.owner_instance AS previous, x.handed_over FROM "
            "matches x LEFT JOIN instances i ON i.id = x.owner_instance WHERE x.finished_ms IS "
            "NULL AND (x.owner_instance IS NULL OR i.id IS NULL OR i.lease_expires < now() OR "
            "($2 AND x.owner_instance = $1) OR (x.handed_over AND x.owner_instance = $1)) "
            "ORDER BY x.created_ms, x.id LIMIT $3 FOR UPDATE OF x SKIP LOCKED) c WHERE m.id = "
            "c.id AND m.owner_epoch = c.owner_epoch "
            "RETURNING m.id, m.owner_epoch, m.room_code, c.previous, c.handed_over",
            options_.instance_id, mine_too, options_.claim_limit);
        std::vector<std::pair<MatchId, MatchOwnership::Owned>> owned;
        std::uint64_t takeovers = 0;
        for (const auto& row : claimed) {
            const MatchId id = row[0].as<std::string>();
            owned.emplace_back(
                id, MatchOwnership::Owned{row[1].as<std::int64_t>(), row[2].as<std::string>()});
            const std::string previous = row[3].is_null() ? "" : row[3].as<std::string>();
            if (row[4].as<bool>()) {
                spdlog::info("cluster: match {} (room {}) handed over to this instance (epoch {})",
                             id, owned.back().second.room_code, owned.back().second.epoch);
            } else if (previous != options_.instance_id) {
                ++takeovers;
                spdlog::info("cluster: match {} (room {}) taken over from {} (epoch {})", id,
                             owned.back().second.room_code,
                             previous.empty() ? std::string("no owner") : "instance " + previous,
                             owned.back().second.epoch);
            }
            out.value.push_back(read_recovered(t, id));
        }
        if (!owned.empty()) {
            // The claimed rooms' codes are this instance's now (docs/cluster.md, "Rooms across
            // the cluster").
            std::vector<std::string> codes;
            for (const auto& [id, o] : owned) {
                codes.push_back(o.room_code);
            }
            t.exec_params("INSERT INTO rooms (code, instance_id) SELECT unnest($1::text[]), $2 "
                          "ON CONFLICT (code) DO UPDATE SET instance_id = excluded.instance_id",
                          text_array(codes), options_.instance_id);
        }
        t.commit();
        for (auto& [id, o] : owned) {
            ownership_->add(id, std::move(o));
        }
        takeovers_total_ += takeovers;
    } catch (const pqxx::broken_connection& e) {
        drop_connection();
        out.error = error_from(e, shown_, "claiming matches on");
    } catch (const std::exception& e) {
        out.error = error_from(e, shown_, "claiming matches on");
    }
    return out;
}

void PostgresCluster::write_lease(pqxx::transaction_base& t, bool registering) {
    const pqxx::result r = t.exec_params(
        "INSERT INTO instances (id, public_url, lease_expires) VALUES ($1, $2, now() + " +
            lease_interval(3) + ") ON CONFLICT (id) DO UPDATE SET " +
            (registering ? "public_url = excluded.public_url, started_at = now(), " : "") +
            "lease_expires = excluded.lease_expires RETURNING " + unix_ms("lease_expires"),
        options_.instance_id, options_.public_url,
        static_cast<std::int64_t>(options_.lease.count()));
    lease_expires_ms_ = r[0][0].as<std::int64_t>();
}

bool PostgresCluster::renew() {
    pqxx::work t(connection());
    const pqxx::result old =
        t.exec_params("SELECT lease_expires < now() FROM instances WHERE id = $1 FOR UPDATE",
                      options_.instance_id);
    write_lease(t, false);
    t.commit();
    lease_ok_ = true;
    if (old.empty() || old[0][0].as<bool>()) {
        spdlog::warn("cluster: the lease of instance {} had expired; renewed (its matches that "
                     "another instance claimed meanwhile stop here)",
                     options_.instance_id);
        return true;
    }
    return false;
}

void PostgresCluster::check_owned() {
    const auto owned = ownership_->all();
    if (owned.empty()) {
        return;
    }
    std::vector<std::string> ids;
    for (const auto& [id, o] : owned) {
        ids.push_back(id);
    }
    std::unordered_map<MatchId, std::pair<std::string, std::int64_t>> now;
    {
        pqxx::work t(connection());
        for (const auto& row :
             t.exec_params("SELECT id, coalesce(owner_instance, ''), owner_epoch FROM matches "
                           "WHERE id = ANY($1::text[])",
                           text_array(ids))) {
            now[row[0].as<std::string>()] = {row[1].as<std::string>(), row[2].as<std::int64_t>()};
        }
        t.commit();
    }
    for (const auto& [id, o] : owned) {
        const auto it = now.find(id);
        if (it == now.end()) {
            continue; // created, not yet written
        }
        if (it->second.first != options_.instance_id || it->second.second != o.epoch) {
            spdlog::warn("cluster: match {} (room {}) is owned by instance {} now; its room here "
                         "stops",
                         id, o.room_code, it->second.first);
            ownership_->lost(id);
        }
    }
}

void PostgresCluster::round() {
    try {
        const auto now = std::chrono::steady_clock::now();
        if (renew() || failing_) {
            // Back from a freeze or an outage, in which every lease may have lapsed: the other
            // instances get a lease's time to renew theirs before this one claims any match.
            claims_from_ = now + options_.lease;
        }
        if (failing_) {
            spdlog::info("cluster: lease renewed again");
            failing_ = false;
        }
        check_owned();
        if (now < claims_from_) {
            return;
        }
        auto claimed = claim(false);
        if (!claimed.ok()) {
            throw std::runtime_error(claimed.error->message);
        }
        if (!claimed.value.empty() && handlers_.on_claimed) {
            handlers_.on_claimed(std::move(claimed.value));
        }
        take_handed_rooms();
    } catch (const std::exception& e) {
        if (dynamic_cast<const pqxx::broken_connection*>(&e) != nullptr) {
            drop_connection();
        }
        lease_ok_ = false;
        if (!failing_) {
            spdlog::error("cluster: instance {} cannot renew its lease or claim matches: {}",
                          options_.instance_id, e.what());
            failing_ = true;
        }
    }
}

void PostgresCluster::take_handed_rooms() {
    pqxx::result handed;
    try {
        pqxx::work t(connection());
        handed = t.exec_params(
            "UPDATE rooms r SET waiting = NULL FROM (SELECT code, waiting FROM rooms WHERE "
            "instance_id = $1 AND waiting IS NOT NULL FOR UPDATE) old WHERE r.code = old.code "
            "RETURNING r.code, old.waiting::text",
            options_.instance_id);
        t.commit();
    } catch (const pqxx::broken_connection&) {
        throw; // the round's: the connection is made again
    } catch (const std::exception& e) {
        spdlog::error("cluster: rooms handed to this instance not taken: {}", e.what());
        return;
    }
    if (handed.empty() || !handlers_.on_rooms_handed) {
        return;
    }
    std::vector<WaitingRoom> rooms;
    for (const auto& row : handed) {
        rooms.push_back(WaitingRoom{row[0].as<std::string>(), row[1].as<std::string>()});
    }
    handlers_.on_rooms_handed(std::move(rooms));
}

void PostgresCluster::start(ClusterHandlers handlers) {
    handlers_ = std::move(handlers);
    ownership_->set_on_lost(handlers_.on_lost);
    directory_.start(handlers_.on_paired);
    thread_ = std::thread([this] { run(); });
}

void PostgresCluster::run() {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
        lock.unlock();
        round();
        wait_for_next_round();
        lock.lock();
    }
}

void PostgresCluster::wait_for_next_round() {
    constexpr auto kSlice = std::chrono::milliseconds(100);
    const auto until = std::chrono::steady_clock::now() + renew_interval();
    for (;;) {
        const auto now = std::chrono::steady_clock::now();
        {
            std::unique_lock lock(mutex_);
            if (stopping_ || now >= until) {
                return;
            }
        }
        const auto slice = std::min<std::chrono::steady_clock::duration>(kSlice, until - now);
        try {
            pqxx::connection& c = connection();
            if (!wake_receiver_) {
                wake_receiver_ = std::make_unique<WakeReceiver>(c, woken_);
            }
            woken_ = false;
            const auto us = std::chrono::duration_cast<std::chrono::microseconds>(slice).count();
            c.await_notification(0, static_cast<long>(us));
            if (woken_) {
                return;
            }
        } catch (const std::exception&) {
            drop_connection(); // the round says so; wait on the clock meanwhile
            std::unique_lock lock(mutex_);
            wake_.wait_for(lock, slice, [this] { return stopping_; });
        }
    }
}

void PostgresCluster::stop() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) {
        thread_.join();
    }
    directory_.stop();
}

Loaded<std::vector<HandedMatch>> PostgresCluster::hand_over(std::vector<WaitingRoom> waiting) {
    Loaded<std::vector<HandedMatch>> out;
    if (!registered_) {
        return out;
    }
    try {
        pqxx::work t(connection());
        // This instance's lease ends in the same transaction: no other instance hands it
        // matches, and what it does not hand over is an orphan for any instance to claim.
        t.exec_params("UPDATE instances SET lease_expires = now() WHERE id = $1",
                      options_.instance_id);
        struct Target {
            std::string id;
            std::string url;
            std::int64_t owned = 0;
        };
        std::vector<Target> targets;
        for (const auto& row : t.exec_params(
                 "SELECT i.id, i.public_url, (SELECT count(*) FROM matches m WHERE "
                 "m.owner_instance = i.id AND m.finished_ms IS NULL) FROM instances i WHERE "
                 "i.id <> $1 AND i.lease_expires > now() ORDER BY i.id",
                 options_.instance_id)) {
            targets.push_back(
                {row[0].as<std::string>(), row[1].as<std::string>(), row[2].as<std::int64_t>()});
        }
        if (targets.empty()) {
            t.commit();
            lease_ok_ = false;
            return out;
        }
        std::vector<std::string> ids;
        std::vector<std::string> codes;
        std::vector<std::string> to;
        for (const auto& row :
             t.exec_params("SELECT id, room_code FROM matches WHERE owner_instance = $1 AND "
                           "finished_ms IS NULL ORDER BY created_ms FOR UPDATE",
                           options_.instance_id)) {
            // The least loaded instance takes the next match.
            Target& target = *std::min_element(
                targets.begin(), targets.end(),
                [](const Target& a, const Target& b) { return a.owned < b.owned; });
            ++target.owned;
            HandedMatch handed{row[0].as<std::string>(), row[1].as<std::string>(), target.id,
                               target.url};
            ids.push_back(handed.match);
            codes.push_back(handed.room_code);
            to.push_back(target.id);
            out.value.push_back(std::move(handed));
        }
        // Then the rooms waiting for their players, the same way (no match: no epoch).
        std::vector<std::string> waiting_codes;
        std::vector<std::string> waiting_to;
        std::vector<std::string> descriptions;
        for (WaitingRoom& room : waiting) {
            Target& target = *std::min_element(
                targets.begin(), targets.end(),
                [](const Target& a, const Target& b) { return a.owned < b.owned; });
            ++target.owned;
            waiting_codes.push_back(room.code);
            waiting_to.push_back(target.id);
            descriptions.push_back(std::move(room.description));
            out.value.push_back(HandedMatch{{}, room.code, target.id, target.url});
        }
        if (!ids.empty()) {
            t.exec_params("UPDATE matches m SET owner_instance = v.target, owner_epoch = "
                          "m.owner_epoch + 1, handed_over = true FROM unnest($1::text[], "
                          "$2::text[]) AS v(id, target) WHERE m.id = v.id",
                          text_array(ids), text_array(to));
            t.exec_params("UPDATE rooms r SET instance_id = v.target FROM unnest($1::text[], "
                          "$2::text[]) AS v(code, target) WHERE r.code = v.code",
                          text_array(codes), text_array(to));
        }
        if (!waiting_codes.empty()) {
            t.exec_params(
                "UPDATE rooms r SET instance_id = v.target, waiting = v.description::jsonb "
                "FROM unnest($1::text[], $2::text[], $3::text[]) AS v(code, target, "
                "description) WHERE r.code = v.code AND r.instance_id = $4",
                text_array(waiting_codes), text_array(waiting_to), text_array(descriptions),
                options_.instance_id);
        }
        if (!out.value.empty()) {
            t.exec(std::string("NOTIFY ") + kWakeChannel);
        }
        t.commit();
        lease_ok_ = false;
        for (const auto& handed : out.value) {
            if (handed.match.empty()) {
                spdlog::info(
                    "cluster: room {} (waiting for its players) handed over to instance {}",
                    handed.room_code, handed.instance_id);
                continue;
            }
            ownership_->finished(handed.match); // not lost: handed on, its room stopped
            spdlog::info("cluster: match {} (room {}) handed over to instance {}", handed.match,
                         handed.room_code, handed.instance_id);
        }
    } catch (const std::exception& e) {
        drop_connection();
        out.value.clear();
        out.error = error_from(e, shown_, "handing matches over on");
    }
    return out;
}

void PostgresCluster::end_lease() {
    if (!registered_) {
        return;
    }
    try {
        pqxx::work t(connection());
        t.exec_params("UPDATE instances SET lease_expires = now() WHERE id = $1",
                      options_.instance_id);
        t.commit();
        lease_ok_ = false;
        spdlog::info("cluster: lease of instance {} ended", options_.instance_id);
    } catch (const std::exception& e) {
        spdlog::warn("cluster: the lease of instance {} could not be ended (it expires by "
                     "itself): {}",
                     options_.instance_id, e.what());
    }
}

ClusterStatus PostgresCluster::status() const {
    ClusterStatus s;
    s.instance_id = options_.instance_id;
    s.public_url = options_.public_url;
    s.lease_expires_ms = lease_expires_ms_.load();
    s.lease_ok = lease_ok_.load();
    s.matches_owned = ownership_->size();
    s.takeovers_total = takeovers_total_.load();
    s.matches_lost_total = ownership_->lost_total();
    return s;
}

} // namespace carrom::store::postgres
