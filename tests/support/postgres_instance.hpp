#pragma once
// A PostgreSQL server of the tests' own: initdb in a fresh temporary directory, as an
// unprivileged user when the tests run as root (initdb refuses root; the directory then belongs
// to nobody), the server started with pg_ctl listening only on a Unix socket in that directory,
// and stopped (immediately) and removed with the directory when the object goes. The superuser
// is "carrom", trusted on the socket: tests connect with postgresql://carrom@/DB?host=DIR.
//
// The programs come from CARROM_PG_BINDIR if set, else the newest /usr/lib/postgresql/N/bin
// (Debian's postgresql package), else `pg_config --bindir`.

#include "support/command_run.hpp"

#include <string>

namespace carrom::test_support {

class PostgresInstance {
public:
    // initdb and start; throws std::runtime_error with the command's output when either fails.
    PostgresInstance();
    ~PostgresInstance();
    PostgresInstance(const PostgresInstance&) = delete;
    PostgresInstance& operator=(const PostgresInstance&) = delete;

    // The URL of a database on this server, as user.
    std::string url(const std::string& database, const std::string& user = "carrom") const;
    // A new empty database (named t1, t2, ... in order) owned by owner; returns its name.
    std::string create_database(const std::string& owner = "carrom");
    // Runs SQL through psql as the superuser in database; the output of a query (unaligned,
    // tuples only), exit 0 on success.
    CommandRun sql(const std::string& database, const std::string& statements) const;

    // Stops the server (fast shutdown: sessions are ended) and starts it again, on the same data
    // and socket. True on success.
    bool stop();
    bool start();

    const std::string& directory() const { return directory_; }
    // Where initdb, pg_ctl, postgres and psql are.
    static std::string bindir();

private:
    // cmd run as the server's user (setpriv to nobody when this process is root).
    CommandRun as_server_user(const std::string& cmd) const;

    std::string directory_; // socket directory; data in directory_/data, log in directory_/log
    std::string bin_;
    int databases_ = 0;
    bool running_ = false;
};

} // namespace carrom::test_support
