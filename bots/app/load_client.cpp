#include "load_client.hpp"

#include "message_head.hpp"

#include "carrom/bots/match_view.hpp"
#include "carrom/proto/codec.hpp"
#include "carrom/tls/client_tls.hpp"

#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/websocket/stream.hpp>

#include <algorithm>
#include <deque>
#include <random>

namespace carrom::load {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

// The messages a player acts on, decoded whole; the others (pong, the events of a shot's
// physics and the rules' cues) are only counted.
bool acts_on(const MessageHead& head) {
    if (head.type == "event") {
        return head.kind == "turn" || head.kind == "game_end";
    }
    return head.type != "pong";
}

} // namespace

class MatchPair::Player : public std::enable_shared_from_this<MatchPair::Player> {
public:
    Player(asio::io_context& ioc, MatchPair& pair, const LoadOptions& options, LoadStats& stats,
           bool creator, int generation, std::uint64_t seed)
        : pair_(pair), options_(options), stats_(stats), creator_(creator), generation_(generation),
          port_(options.server.port()), ws_(ioc), think_(ioc),
          think_rng_(seed ^ 0x9e3779b97f4a7c15ULL), strategy_(seed) {}

    void start(std::string code) {
        code_ = std::move(code);
        beast::get_lowest_layer(ws_).expires_after(std::chrono::seconds(30));
        beast::get_lowest_layer(ws_).async_connect(
            tcp::endpoint(options_.server.address(), port_),
            [self = shared_from_this()](beast::error_code ec) { self->on_connect(ec); });
    }

    // Starts where a redirect sent the player it replaces (the room it was in: `code`).
    void start_redirected(std::string code, const RedirectPlan& plan) {
        plan_ = plan;
        port_ = plan.port;
        target_ = plan.target;
        start(std::move(code));
    }

    const std::string& room_code() const { return code_; }

    bool held() const { return open_ && seated_ && !broken_; }

    // Leaves the room and closes the connection; a player still connecting closes once its
    // connection opens.
    void close() {
        if (closing_) {
            return;
        }
        closing_ = true;
        think_.cancel();
        if (open_) {
            send(proto::encode(proto::Leave{}));
        }
    }

private:
    void on_connect(beast::error_code ec) {
        if (ec) {
            return fail();
        }
        if (closing_) {
            beast::get_lowest_layer(ws_).close();
            return;
        }
        if (options_.tls) {
            if (!tls::start_client_tls(ws_.next_layer(), options_.tls,
                                       options_.server.address().to_string(), verify_failure_)) {
                return fail();
            }
            ws_.next_layer().tls().async_handshake(
                asio::ssl::stream_base::client,
                [self = shared_from_this()](beast::error_code e) { self->on_tls_handshake(e); });
            return;
        }
        websocket_handshake();
    }

    void on_tls_handshake(beast::error_code ec) {
        if (ec) {
            if (stats_.tls_refusal.empty()) {
                stats_.tls_refusal =
                    tls::tls_handshake_error_text(options_.server.address().to_string() + ":" +
                                                      std::to_string(options_.server.port()),
                                                  ec, verify_failure_);
            }
            return fail();
        }
        websocket_handshake();
    }

    void websocket_handshake() {
        beast::get_lowest_layer(ws_).expires_never();
        ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::client));
        ws_.read_message_max(proto::kMaxServerMessageBytes);
        ws_.async_handshake("127.0.0.1", target_, [self = shared_from_this()](beast::error_code e) {
            self->on_handshake(e);
        });
    }

    void on_handshake(beast::error_code ec) {
        if (ec) {
            return fail();
        }
        open_ = true;
        ws_.text(true);
        read();
        if (closing_) {
            close_sent_ = true;
            ws_.async_close(websocket::close_code::normal,
                            [self = shared_from_this()](beast::error_code) {});
            return;
        }
        send(proto::encode(proto::Hello{
            proto::kProtocolVersion, creator_ ? "load-a" : "load-b",
            plan_.token.empty() ? std::nullopt : std::optional(plan_.token), std::nullopt, true}));
    }

    void read() {
        ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
            self->on_read(ec);
        });
    }

    void on_read(beast::error_code ec) {
        if (ec) {
            if (!closing_) {
                fail();
            }
            open_ = false;
            return;
        }
        const auto data = buffer_.cdata();
        const std::string_view text(static_cast<const char*>(data.data()), data.size());
        on_text(text);
        buffer_.consume(buffer_.size());
        read();
    }

    void on_text(std::string_view text) {
        const auto now = Clock::now();
        ++stats_.messages;
        stats_.bytes += static_cast<std::int64_t>(text.size());
        if (moving_) {
            moving_bytes_ += static_cast<double>(text.size());
        }
        const auto head = read_message_head(text);
        if (!head.ok()) {
            ++stats_.malformed;
            return;
        }
        if (head.message->type == "snapshot") {
            return on_snapshot(head.message->snapshot, text.size(), now);
        }
        if (!acts_on(*head.message)) {
            return;
        }
        auto decoded = proto::decode_server(text);
        if (!decoded.ok()) {
            ++stats_.malformed;
            return;
        }
        std::visit([&](const auto& m) { on_message(m, now); }, *decoded.message);
    }

    void on_snapshot(const SnapshotFields& snapshot, std::size_t bytes, Clock::time_point now) {
        ++stats_.snapshots;
        if (snapshot.keyframe || pair_.shot_turn < 0) {
            return;
        }
        if (!moving_) {
            moving_ = true;
            moving_since_ = now;
            moving_bytes_ = static_cast<double>(bytes);
        }
        // Lateness against the room's schedule: receive time minus the time the room's schedule
        // (every change of motion plus the regular rate) wanted this delta sent (due_ms, the
        // server's steady clock; steady_clock is CLOCK_MONOTONIC, shared by every process on
        // this host).
        if (!options_.keep_samples) {
            return;
        }
        if (snapshot.due_ms && stats_.measuring) {
            const double now_ms =
                std::chrono::duration<double, std::milli>(now.time_since_epoch()).count();
            stats_.lag_ms.push_back(now_ms - static_cast<double>(*snapshot.due_ms));
            stats_.lag_due_ms.push_back(*snapshot.due_ms);
        }
        // The relative figure: receive time minus the snapshot's match time, minus the shot's
        // smallest such value (end_moving()).
        const double since_shot_ms =
            std::chrono::duration<double, std::milli>(now - pair_.shot_sent_at).count();
        shot_offsets_ms_.push_back(since_shot_ms - snapshot.t_s * 1000.0);
    }

    void end_moving(Clock::time_point now) {
        if (!moving_) {
            return;
        }
        moving_ = false;
        if (stats_.measuring && !shot_offsets_ms_.empty()) {
            const double fastest =
                *std::min_element(shot_offsets_ms_.begin(), shot_offsets_ms_.end());
            for (const double offset : shot_offsets_ms_) {
                stats_.relative_lag_ms.push_back(offset - fastest);
            }
        }
        shot_offsets_ms_.clear();
        if (stats_.measuring) {
            stats_.moving_bytes += moving_bytes_;
            stats_.moving_seconds += std::chrono::duration<double>(now - moving_since_).count();
        }
    }

    void on_message(const proto::Welcome& welcome, Clock::time_point) {
        token_ = welcome.resume_token;
        if (!plan_.token.empty() && welcome.resume_token == plan_.token) {
            return; // the seat is back: the room's state follows
        }
        if (!plan_.code.empty()) {
            send(proto::encode(proto::JoinRoom{plan_.code, plan_.as}));
        } else if (creator_) {
            proto::CreateRoom create;
            create.rule_set = options_.rule_set;
            create.options.shot_clock_s = 0.0;
            create.options.target_points = options_.target_points;
            create.options.boards = 99;
            send(proto::encode(create));
        } else {
            send(proto::encode(proto::JoinRoom{code_, proto::Role::Player}));
        }
    }

    void on_message(const proto::RoomState& room, Clock::time_point) {
        if (creator_ && code_.empty()) {
            code_ = room.code;
            pair_.on_room_code(generation_, room.code);
        }
        plan_.redirects = 0; // in a room: the redirects in a row start again
        seated_ = room.you >= 0 && room.seats.size() == 2 && room.seats[0].occupied &&
                  room.seats[1].occupied;
        room_ = room;
        maybe_shoot();
    }

    void on_message(const proto::Event& event, Clock::time_point now) {
        if (const auto* turn = std::get_if<proto::TurnEvent>(&event)) {
            end_moving(now);
            if (room_) {
                room_->turn = turn->turn;
                room_->to_play = turn->seat;
                room_->phase = proto::Phase::Aiming;
            }
            maybe_shoot();
        } else if (std::holds_alternative<proto::GameEndEvent>(event)) {
            end_moving(now);
            if (options_.replace) {
                pair_.on_game_end(generation_);
            } else {
                if (creator_) {
                    ++stats_.matches_finished;
                }
                send(proto::encode(proto::Rematch{}));
            }
        }
    }

    void on_message(const proto::ShotResult& result, Clock::time_point now) {
        end_moving(now);
        if (room_ && result.seat == room_->you && stats_.measuring) {
            ++stats_.shots;
        }
    }

    void on_message(const proto::Error& error, Clock::time_point) {
        ++stats_.errors;
        ++stats_.errors_by_code[error.code];
        if (error.code == proto::code::kIllegalPlacement ||
            error.code == proto::code::kIllegalShot) {
            last_turn_ = -1;
            maybe_shoot();
        }
    }

    void on_message(const proto::Snapshot&, Clock::time_point) {}
    void on_message(const proto::Pong&, Clock::time_point) {}
    // Followed as plan_redirect() decides: a new player of this role takes this one's place.
    void on_message(const proto::Redirect& redirect, Clock::time_point) {
        const LoadLink link{options_.server, port_, target_, options_.tls != nullptr,
                            plan_.redirects};
        const auto plan =
            plan_redirect(link, redirect, room_ && room_->you >= 0 ? token_ : std::string());
        stop_reading_here();
        if (const auto* refusal = std::get_if<std::string>(&plan)) {
            ++stats_.redirects_refused;
            if (stats_.redirect_refusal.empty()) {
                stats_.redirect_refusal = *refusal;
            }
            return fail();
        }
        ++stats_.redirects;
        pair_.on_redirect(this, std::get<RedirectPlan>(plan));
    }

    // This connection ends without a leave (the server closes it, 4005); its end is no failure.
    void stop_reading_here() {
        closing_ = true;
        think_.cancel();
        while (outbox_.size() > (writing_ ? 1U : 0U)) {
            outbox_.pop_back();
        }
        if (!writing_) {
            write_next(); // sends the close
        }
    }

    void maybe_shoot() {
        if (!room_ || closing_ || room_->you < 0 || room_->phase != proto::Phase::Aiming ||
            room_->to_play != room_->you || room_->turn == last_turn_) {
            return;
        }
        last_turn_ = room_->turn;
        const int turn = room_->turn;
        think_.expires_after(think_delay());
        think_.async_wait([self = shared_from_this(), turn](beast::error_code ec) {
            if (!ec) {
                self->shoot(turn);
            }
        });
    }

    std::chrono::milliseconds think_delay() {
        const auto spread = options_.think_spread.count();
        if (spread <= 0) {
            return options_.think;
        }
        std::uniform_int_distribution<std::int64_t> offset(-spread, spread);
        return std::max(std::chrono::milliseconds(0),
                        options_.think + std::chrono::milliseconds(offset(think_rng_)));
    }

    void shoot(int turn) {
        if (!room_ || closing_) {
            return;
        }
        const auto state = bots::match_state_from(*room_);
        const Shot shot = strategy_.choose_shot(state, room_->you, bots::DecisionBudget{});
        pair_.shot_sent_at = Clock::now();
        pair_.shot_turn = turn;
        send(proto::encode(proto::Shoot{turn, shot.x_px, shot.angle_rad, shot.power}));
    }

    void send(std::string text) {
        if (!open_) {
            return;
        }
        outbox_.push_back(std::move(text));
        if (!writing_) {
            write_next();
        }
    }

    void write_next() {
        if (outbox_.empty() || !open_) {
            writing_ = false;
            if (closing_ && open_ && !close_sent_) {
                close_sent_ = true;
                ws_.async_close(websocket::close_code::normal,
                                [self = shared_from_this()](beast::error_code) {});
            }
            return;
        }
        writing_ = true;
        ws_.async_write(asio::buffer(outbox_.front()),
                        [self = shared_from_this()](beast::error_code ec, std::size_t) {
                            self->outbox_.pop_front();
                            if (ec) {
                                self->writing_ = false;
                                return;
                            }
                            self->write_next();
                        });
    }

    void fail() {
        if (!broken_) {
            broken_ = true;
            ++stats_.failures;
        }
        open_ = false;
    }

    MatchPair& pair_;
    LoadOptions options_;
    LoadStats& stats_;
    bool creator_;
    int generation_;     // of the pair's slot
    std::uint16_t port_; // the server's, or a redirect's
    std::string target_ = "/";
    RedirectPlan plan_; // where a redirect sent this player (empty: nowhere)
    std::string token_; // the welcome's resume token
    websocket::stream<tls::FlexStream<beast::tcp_stream>> ws_;
    tls::VerifyFailure verify_failure_; // the certificate refused in the TLS handshake
    asio::steady_timer think_;
    std::mt19937_64 think_rng_; // the spread of think delays
    beast::flat_buffer buffer_;
    std::deque<std::string> outbox_;
    bool writing_ = false;
    bool open_ = false;
    bool seated_ = false;
    bool broken_ = false;
    bool closing_ = false;
    bool close_sent_ = false;
    std::string code_;
    std::optional<proto::RoomState> room_;
    int last_turn_ = -1;
    bots::RandomStrategy strategy_;
    bool moving_ = false;
    Clock::time_point moving_since_{};
    double moving_bytes_ = 0.0;
    std::vector<double> shot_offsets_ms_; // this shot's (receive - match time), ms
};

LoadCounts& LoadCounts::operator+=(const LoadCounts& other) {
    messages += other.messages;
    bytes += other.bytes;
    snapshots += other.snapshots;
    malformed += other.malformed;
    shots += other.shots;
    errors += other.errors;
    failures += other.failures;
    redirects += other.redirects;
    redirects_refused += other.redirects_refused;
    matches_started += other.matches_started;
    matches_finished += other.matches_finished;
    return *this;
}

LoadStats& LoadStats::operator+=(const LoadStats& other) {
    LoadCounts::operator+=(other);
    if (tls_refusal.empty()) {
        tls_refusal = other.tls_refusal;
    }
    if (redirect_refusal.empty()) {
        redirect_refusal = other.redirect_refusal;
    }
    for (const auto& [code, count] : other.errors_by_code) {
        errors_by_code[code] += count;
    }
    lag_ms.insert(lag_ms.end(), other.lag_ms.begin(), other.lag_ms.end());
    lag_due_ms.insert(lag_due_ms.end(), other.lag_due_ms.begin(), other.lag_due_ms.end());
    relative_lag_ms.insert(relative_lag_ms.end(), other.relative_lag_ms.begin(),
                           other.relative_lag_ms.end());
    moving_bytes += other.moving_bytes;
    moving_seconds += other.moving_seconds;
    return *this;
}

MatchPair::MatchPair(asio::io_context& ioc, const LoadOptions& options, LoadStats& stats,
                     std::uint64_t seed)
    : ioc_(ioc), options_(options), stats_(stats), seed_(seed) {}

MatchPair::~MatchPair() = default;

namespace {

// The players' seeds of a generation: the first one's as they always were, later ones apart so
// that a new match does not replay the previous one.
std::uint64_t player_seed(std::uint64_t pair_seed, int generation, bool creator) {
    const std::uint64_t later = static_cast<std::uint64_t>(generation) - 1U;
    const std::uint64_t apart = 0x9e3779b97f4a7c15U;
    return pair_seed * 2U + (creator ? 1U : 2U) + later * apart;
}

} // namespace

void MatchPair::start() {
    ++generation_;
    ++stats_.matches_started;
    shot_turn = -1;
    joiner_.reset();
    creator_ = std::make_shared<Player>(ioc_, *this, options_, stats_, true, generation_,
                                        player_seed(seed_, generation_, true));
    creator_->start("");
}

void MatchPair::on_room_code(int generation, const std::string& code) {
    if (generation != generation_) {
        return;
    }
    joiner_ = std::make_shared<Player>(ioc_, *this, options_, stats_, false, generation_,
                                       player_seed(seed_, generation_, false));
    joiner_->start(code);
}

void MatchPair::on_game_end(int generation) {
    if (generation != generation_) {
        return; // the other player's game_end of a match already replaced
    }
    ++stats_.matches_finished;
    close();
    start();
}

void MatchPair::on_redirect(const Player* from, const RedirectPlan& plan) {
    const bool creator = from == creator_.get();
    if (!creator && from != joiner_.get()) {
        return; // a player of a match already replaced
    }
    auto next = std::make_shared<Player>(ioc_, *this, options_, stats_, creator, generation_,
                                         player_seed(seed_, generation_, creator));
    next->start_redirected(from->room_code(), plan);
    (creator ? creator_ : joiner_) = std::move(next);
}

bool MatchPair::held() const {
    return creator_ && joiner_ && creator_->held() && joiner_->held();
}

void MatchPair::close() {
    if (creator_) {
        creator_->close();
    }
    if (joiner_) {
        joiner_->close();
    }
}

} // namespace carrom::load
