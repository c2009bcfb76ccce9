#pragma once
// The C API's one error text (carrom_error, engine_api.h), shared by its two halves.

#include <string_view>

namespace carrom::wasm {

// carrom_error returns `code` until the next call that sets it.
void set_api_error(std::string_view code);

} // namespace carrom::wasm
