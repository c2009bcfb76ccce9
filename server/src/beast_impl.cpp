// Compiles Boost.Asio and Boost.Beast once for the whole program (separate compilation:
// BOOST_ASIO_SEPARATE_COMPILATION and BOOST_BEAST_SEPARATE_COMPILATION are set on
// carrom_server_lib and everything linking it).
#include <boost/asio/impl/src.hpp>
#include <boost/beast/src.hpp>
