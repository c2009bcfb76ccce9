#pragma once
// Golden cases of the plain words both clients say the same way (client/src/plain_words.cpp,
// web/js/plain_words.js): counts, pocket lists, queen sentences, the server's errors and the
// rule sets' names. The errors each client says its own way (a page is reloaded, a client
// updated; tabs and windows) are left out (tests/golden/README.md).

#include <nlohmann/json.hpp>

namespace carrom::golden {

// Input {"count": [[n, one, many]], "pockets": [[kind...]], "queen": [[state, seat, name]],
// "errors": [[code, message]], "rule_sets": [name]}; output: the same keys, one sentence per
// input.
nlohmann::json replay_words(const nlohmann::json& input);
nlohmann::json words_input();

} // namespace carrom::golden
