#pragma once
// A byte stream that is plain (Next) or TLS over Next (Beast's ssl_stream), chosen at run time:
// the server decides after the first bytes of a connection (Beast's TLS detection), a client by
// its URL's scheme. WebSocket and HTTP code then serve both with one type. It meets Asio's
// AsyncReadStream and AsyncWriteStream and Beast's teardown for websocket::stream.
//
// Invariants: is_tls() never turns false again; the TLS context stays alive as long as the
// stream (a reload of the server's certificate gives new connections a new context, never this
// one another).

#include <boost/asio/ssl/context.hpp>
#include <boost/beast/core/error.hpp>
#include <boost/beast/core/role.hpp>
#include <boost/beast/ssl/ssl_stream.hpp>
#include <boost/beast/websocket/teardown.hpp>

#include <memory>
#include <type_traits>
#include <utility>
#include <variant>

namespace carrom::tls {

template <class Next> class FlexStream {
public:
    using next_layer_type = Next;
    using executor_type = typename Next::executor_type;
    using tls_stream_type = boost::beast::ssl_stream<Next>;

    // A plain stream made from args (a socket, an executor or an io_context).
    template <class... Args>
    requires std::is_constructible_v<Next, Args&&...>
    explicit FlexStream(Args&&... args)
        : stream_(std::in_place_index<0>, std::forward<Args>(args)...) {}

    FlexStream(FlexStream&&) noexcept = default;
    FlexStream& operator=(FlexStream&&) noexcept = default;

    // From now on everything goes through TLS with this context (handshake first: tls()).
    void use_tls(std::shared_ptr<boost::asio::ssl::context> context) {
        Next next = std::move(std::get<0>(stream_));
        stream_.template emplace<1>(std::move(next), *context);
        context_ = std::move(context);
    }
    bool is_tls() const { return stream_.index() == 1; }
    tls_stream_type& tls() { return std::get<1>(stream_); }

    executor_type get_executor() {
        return std::visit([](auto& s) { return s.get_executor(); }, stream_);
    }
    // The plain stream under the TLS layer (or the stream itself): the socket's options, the
    // peer's address, closing.
    Next& next_layer() {
        if (auto* tls_stream = std::get_if<1>(&stream_)) {
            return tls_stream->next_layer();
        }
        return std::get<0>(stream_);
    }

    template <class MutableBuffers, class Handler>
    void async_read_some(const MutableBuffers& buffers, Handler&& handler) {
        std::visit([&](auto& s) { s.async_read_some(buffers, std::forward<Handler>(handler)); },
                   stream_);
    }
    template <class ConstBuffers, class Handler>
    void async_write_some(const ConstBuffers& buffers, Handler&& handler) {
        std::visit([&](auto& s) { s.async_write_some(buffers, std::forward<Handler>(handler)); },
                   stream_);
    }

    // The end of a WebSocket connection: TLS close_notify, then the TCP shutdown.
    template <class Handler> void async_teardown(boost::beast::role_type role, Handler&& handler) {
        using boost::beast::async_teardown;
        using boost::beast::websocket::async_teardown;
        std::visit([&](auto& s) { async_teardown(role, s, std::forward<Handler>(handler)); },
                   stream_);
    }
    void teardown(boost::beast::role_type role, boost::beast::error_code& ec) {
        using boost::beast::teardown;
        using boost::beast::websocket::teardown;
        std::visit([&](auto& s) { teardown(role, s, ec); }, stream_);
    }

private:
    std::variant<Next, tls_stream_type> stream_;
    std::shared_ptr<boost::asio::ssl::context> context_;
};

// Beast's websocket::stream finds these by argument-dependent lookup.
template <class Next, class Handler>
void async_teardown(boost::beast::role_type role, FlexStream<Next>& stream, Handler&& handler) {
    stream.async_teardown(role, std::forward<Handler>(handler));
}
template <class Next>
void teardown(boost::beast::role_type role, FlexStream<Next>& stream,
              boost::beast::error_code& ec) {
    stream.teardown(role, ec);
}

} // namespace carrom::tls
