#pragma once
// The server's clock as seen from this client: offset = server time - local time, from the
// server_time_ms carried by welcome, room_state, turn events and pongs. Pong samples know the
// round trip, so the offset is taken at its midpoint; the sample with the smallest round trip in
// the recent window wins. Until a pong arrives, one-way samples are used as they are (they are
// late by the one-way latency, which only makes the shot clock look a little shorter).

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

namespace carrom::client {

class ServerClock {
public:
    // A message stamped server_ms arrived at local_s (one-way: latency unknown).
    void one_way(std::int64_t server_ms, double local_s);
    // A pong stamped server_ms answered a ping sent at sent_local_s and arrived at local_s.
    void round_trip(std::int64_t server_ms, double sent_local_s, double local_s);

    bool known() const { return offset_ms_.has_value(); }
    // Server time (ms) now, by the local clock.
    double server_now_ms(double local_s) const;
    // Latest round trip (ms), if any pong arrived.
    std::optional<double> rtt_ms() const { return rtt_ms_; }

private:
    struct Sample {
        double offset_ms;
        double rtt_ms;
    };
    std::optional<double> offset_ms_;
    std::optional<double> rtt_ms_;
    std::deque<Sample> samples_; // pong samples, newest last
};

// Seconds left until deadline_ms (server clock), never negative.
double seconds_until(const ServerClock& clock, std::int64_t deadline_ms, double local_s);

} // namespace carrom::client
