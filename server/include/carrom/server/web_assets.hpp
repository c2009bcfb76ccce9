#pragma once
// The web client (web/) as embedded in the binary at build time by server/cmake/embed_files.cmake
// (library carrom_web_assets). Paths are relative to web/, '/'-separated and sorted.

#include "carrom/server/static_site.hpp"

#include <span>

namespace carrom::server {

std::span<const EmbeddedFile> embedded_web_files();

} // namespace carrom::server
