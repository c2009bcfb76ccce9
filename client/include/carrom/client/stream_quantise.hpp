#pragma once
// Bodies rounded as the server's shot stream rounds them (proto::quantise: 0.01 px and 0.01 px/s),
// without the wire codec's header (whose Decoded clashes with scene_json.hpp's).

#include "carrom/body.hpp"

#include <vector>

namespace carrom::client {

Body stream_quantised(Body body);
std::vector<Body> stream_quantised(std::vector<Body> bodies);

} // namespace carrom::client
