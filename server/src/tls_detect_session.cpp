#include "tls_detect_session.hpp"

#include "http_session.hpp"
#include "server_core.hpp"
#include "tls_context.hpp"

#include <boost/beast/core/bind_handler.hpp>
#include <boost/beast/core/detect_ssl.hpp>
#include <spdlog/spdlog.h>

namespace carrom::server {

TlsDetectSession::TlsDetectSession(ServerCore& core, WsSocket socket)
    : core_(core), stream_(std::move(socket)), deadline_(stream_.get_executor()) {}

TlsDetectSession::~TlsDetectSession() {
    if (address_counted_) {
        core_.remove_address(address_);
    }
}

void TlsDetectSession::run() {
    beast::error_code ec;
    const auto remote = stream_.next_layer().remote_endpoint(ec);
    address_ = ec ? std::string() : remote.address().to_string();
    if (!core_.add_address(address_)) {
        core_.metrics.rejected_connections_total.fetch_add(1, std::memory_order_relaxed);
        spdlog::debug("{}: too many connections from this address; closed before TLS", address_);
        stream_.next_layer().close(ec);
        return;
    }
    address_counted_ = true;
    deadline_.expires_after(to_duration(core_.settings.tls_handshake_timeout_s));
    deadline_.async_wait([weak = weak_from_this()](beast::error_code timer_ec) {
        if (timer_ec) {
            return;
        }
        if (auto self = weak.lock()) {
            self->time_out();
        }
    });
    beast::async_detect_ssl(
        stream_.next_layer(), buffer_,
        beast::bind_front_handler(&TlsDetectSession::on_detect, shared_from_this()));
}

void TlsDetectSession::on_detect(beast::error_code ec, bool tls) {
    if (ec) {
        return; // closed, reset or timed out before the first bytes
    }
    if (!tls) {
        hand_over();
        std::make_shared<HttpSession>(core_, std::move(stream_), std::move(buffer_))->run();
        return;
    }
    handshaking_ = true;
    stream_.use_tls(core_.tls->current());
    stream_.tls().async_handshake(
        asio::ssl::stream_base::server, buffer_.data(),
        beast::bind_front_handler(&TlsDetectSession::on_handshake, shared_from_this()));
}

void TlsDetectSession::on_handshake(beast::error_code ec, std::size_t used) {
    handshaking_ = false;
    if (ec) {
        if (!timed_out_) { // a timed-out handshake was counted by time_out()
            core_.metrics.tls_handshake_failures_total.fetch_add(1, std::memory_order_relaxed);
        }
        spdlog::debug("{}: TLS handshake failed: {}", address_, ec.message());
        return;
    }
    core_.metrics.tls_handshakes_total.fetch_add(1, std::memory_order_relaxed);
    buffer_.consume(used);
    hand_over();
    std::make_shared<HttpSession>(core_, std::move(stream_), std::move(buffer_))->run();
}

void TlsDetectSession::hand_over() {
    handed_over_ = true;
    deadline_.cancel();
    release_address();
}

void TlsDetectSession::time_out() {
    if (handed_over_ || timed_out_) {
        return;
    }
    timed_out_ = true;
    // The books are kept before the socket closes: whoever sees the close sees them done.
    if (handshaking_) {
        core_.metrics.tls_handshake_failures_total.fetch_add(1, std::memory_order_relaxed);
    }
    release_address();
    beast::error_code ignored;
    stream_.next_layer().close(ignored); // pending reads end with an error
}

void TlsDetectSession::release_address() {
    if (address_counted_) {
        core_.remove_address(address_);
        address_counted_ = false;
    }
}

} // namespace carrom::server
