#include "carrom/client/stream_quantise.hpp"

#include "carrom/proto/codec.hpp"

namespace carrom::client {

Body stream_quantised(Body body) {
    body.pos_px = {proto::quantise(body.pos_px.x), proto::quantise(body.pos_px.y)};
    body.vel_px_s = {proto::quantise(body.vel_px_s.x), proto::quantise(body.vel_px_s.y)};
    return body;
}

std::vector<Body> stream_quantised(std::vector<Body> bodies) {
    for (Body& body : bodies) {
        body = stream_quantised(body);
    }
    return bodies;
}

} // namespace carrom::client
