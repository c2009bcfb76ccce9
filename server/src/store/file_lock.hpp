#pragma once
// An exclusive advisory lock (flock) on a file of its own, held for the object's lifetime: one
// carrom-server per database. The lock file sits next to the database ("<db>.lock"); it is never
// the database itself, whose POSIX locks belong to SQLite (closing any other descriptor of the
// database file would drop them).

#include <string>

namespace carrom::store {

class FileLock {
public:
    FileLock() = default;
    ~FileLock();
    FileLock(FileLock&& other) noexcept;
    FileLock& operator=(FileLock&& other) noexcept;
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

    enum class Result {
        Acquired,
        Busy,   // another process holds it
        Failed, // the file cannot be created or locked
    };
    // Creates path if needed and locks it without waiting. Unless Acquired, error is one
    // sentence.
    Result acquire(const std::string& path, std::string& error);
    bool held() const { return fd_ >= 0; }

private:
    void release();
    int fd_ = -1;
};

} // namespace carrom::store
