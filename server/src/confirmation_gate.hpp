#pragma once
// Private to server/src: the way from the match store's writer thread into the rooms. A write
// confirmation (store::OnWritten) passes only while the gate is open; Server::shutdown closes it
// before the rooms and the io_context are destroyed, so that a store that outlives the server
// (carrom-server's main keeps its own reference) never posts to a room or an io_context that is
// gone. Boost-free.

#include <functional>
#include <mutex>

namespace carrom::server {

class ConfirmationGate {
public:
    // Runs f (under the gate's lock) while the gate is open; false when it is closed.
    bool pass(const std::function<void()>& f);
    // From now on nothing passes; returns once a pass in progress has finished.
    void close();

private:
    std::mutex mutex_;
    bool closed_ = false;
};

} // namespace carrom::server
