#pragma once
// Bodies rounded as the server's shot stream rounds them (proto::quantise: 0.01 px and 0.01 px/s),
// so that a replay shows what a live client was sent.

#include "carrom/body.hpp"

#include <vector>

namespace carrom::client {

Body stream_quantised(Body body);
std::vector<Body> stream_quantised(std::vector<Body> bodies);

} // namespace carrom::client
