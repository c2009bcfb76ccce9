#include "carrom/room/room_counters.hpp"

namespace carrom::room {

void RoomCounters::observe_snapshot_lag_ms(double lag_ms) {
    for (std::size_t i = 0; i < kLagBucketsMs.size(); ++i) {
        if (lag_ms <= kLagBucketsMs[i]) {
            lag_buckets[i].fetch_add(1, std::memory_order_relaxed);
        }
    }
    lag_count.fetch_add(1, std::memory_order_relaxed);
    lag_sum_us.fetch_add(static_cast<std::int64_t>(lag_ms * 1000.0), std::memory_order_relaxed);
}

} // namespace carrom::room
