#pragma once
// A fresh directory under the system's temporary directory (mkdtemp), removed with everything in
// it when the object goes.

#include <string>
#include <string_view>

namespace carrom::test_support {

class TempDir {
public:
    // prefix: the start of the directory's name, e.g. "carrom_recovery".
    explicit TempDir(std::string_view prefix);
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::string& path() const { return path_; }
    std::string file(const std::string& name) const; // path()/name

private:
    std::string path_;
};

} // namespace carrom::test_support
