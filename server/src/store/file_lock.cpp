#include "store/file_lock.hpp"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace carrom::store {

FileLock::~FileLock() {
    release();
}

FileLock::FileLock(FileLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

FileLock& FileLock::operator=(FileLock&& other) noexcept {
    if (this != &other) {
        release();
        fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
}

void FileLock::release() {
    if (fd_ >= 0) {
        ::close(fd_); // closing the descriptor drops the flock
        fd_ = -1;
    }
}

FileLock::Result FileLock::acquire(const std::string& path, std::string& error) {
    release();
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        error = "cannot create the lock file " + path + ": " + std::strerror(errno);
        return Result::Failed;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int e = errno;
        ::close(fd);
        if (e == EWOULDBLOCK) {
            error = "another carrom-server uses it (it holds " + path + ")";
            return Result::Busy;
        }
        error = "cannot lock " + path + ": " + std::strerror(e);
        return Result::Failed;
    }
    fd_ = fd;
    return Result::Acquired;
}

} // namespace carrom::store
