#include "confirmation_gate.hpp"

namespace carrom::server {

bool ConfirmationGate::pass(const std::function<void()>& f) {
    const std::lock_guard lock(mutex_);
    if (closed_) {
        return false;
    }
    f();
    return true;
}

void ConfirmationGate::close() {
    const std::lock_guard lock(mutex_);
    closed_ = true;
}

} // namespace carrom::server
