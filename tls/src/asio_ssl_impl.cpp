// Compiles Boost.Asio's SSL support once for the whole program (separate compilation, like
// beast/beast_impl.cpp for the rest of Asio and Beast).
#include <boost/asio/ssl/impl/src.hpp>
