// Compiles Boost.Asio and Boost.Beast once for the whole program (separate compilation: the
// carrom_beast target sets BOOST_ASIO_SEPARATE_COMPILATION and BOOST_BEAST_SEPARATE_COMPILATION
// for everything that links it).
#include <boost/asio/impl/src.hpp>
#include <boost/beast/src.hpp>
