#pragma once
// A player's identity key on disk (docs/ratings.md, "Identity"): 64 lowercase hex digits (256
// bits from the operating system's CSPRNG, getrandom), one line, in a file only its owner may
// read (mode 0600). carrom-client keeps it at default_identity_path(); carrom-client and
// carrom-bot take --identity FILE. A lost file is a lost identity: the server keeps only a hash.

#include <optional>
#include <string>

namespace carrom::net {

struct LoadedIdentity {
    std::string key;                  // set when !error
    bool created = false;             // the file did not exist and was written now
    std::optional<std::string> error; // one sentence naming the path
};

// Reads the key in path; when the file does not exist, creates it (and its directory, mode
// 0700) with a new key. A file that holds anything but one key (and a newline) is an error,
// never overwritten.
LoadedIdentity load_or_create_identity(const std::string& path);

// $XDG_CONFIG_HOME/carrom/identity, else $HOME/.config/carrom/identity; "" without either.
std::string default_identity_path();

} // namespace carrom::net
