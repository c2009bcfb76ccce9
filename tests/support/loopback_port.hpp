#pragma once
// A TCP port of 127.0.0.1 that is free when asked, for a server whose address must be known
// before it starts (a cluster instance's --public-url). 0 when none could be found.

#include <cstdint>

namespace carrom::test_support {

std::uint16_t unused_loopback_port();

} // namespace carrom::test_support
