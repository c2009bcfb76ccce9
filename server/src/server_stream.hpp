#pragma once
// Private to server/src: the stream type of every accepted connection, plain or TLS (decided by
// TlsDetectSession when the server has a certificate; always plain without one).

#include "asio_types.hpp"

#include "carrom/tls/flex_stream.hpp"

#include <boost/asio/basic_stream_socket.hpp>
#include <boost/asio/strand.hpp>

namespace carrom::server {

// A connection's socket, with its strand as a concrete executor type: every read, write and post
// goes to the strand directly. Beast's tcp_stream carries a type-erased executor, which costs a
// heap allocation and reference counting for each asynchronous operation (the profile of the
// server under load showed them among its largest costs).
using WsStrand = asio::strand<asio::io_context::executor_type>;
using WsSocket = asio::basic_stream_socket<tcp, WsStrand>;
using ServerStream = tls::FlexStream<WsSocket>;

} // namespace carrom::server
