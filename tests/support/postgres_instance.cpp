#include "support/postgres_instance.hpp"

#include <pwd.h>
#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>

namespace carrom::test_support {
namespace {

namespace fs = std::filesystem;

// Single quotes for /bin/sh.
std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) {
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out + "'";
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) {
        s.pop_back();
    }
    return s;
}

} // namespace

std::string PostgresInstance::bindir() {
    if (const char* env = std::getenv("CARROM_PG_BINDIR"); env != nullptr && *env != '\0') {
        return env;
    }
    std::string best;
    int best_version = -1;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator("/usr/lib/postgresql", ec)) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos || name.empty() ||
            !fs::exists(entry.path() / "bin" / "initdb", ec)) {
            continue;
        }
        if (std::stoi(name) > best_version) {
            best_version = std::stoi(name);
            best = (entry.path() / "bin").string();
        }
    }
    if (!best.empty()) {
        return best;
    }
    return trimmed(run_command("pg_config --bindir 2>/dev/null").out);
}

PostgresInstance::PostgresInstance() : bin_(bindir()) {
    std::string pattern = (fs::temp_directory_path() / "carrom_pg_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        throw std::runtime_error("mkdtemp failed for " + pattern);
    }
    directory_ = pattern;
    if (::geteuid() == 0) {
        const passwd* nobody = ::getpwnam("nobody");
        if (nobody == nullptr || ::chown(directory_.c_str(), nobody->pw_uid, nobody->pw_gid) != 0) {
            throw std::runtime_error("cannot give " + directory_ + " to the user nobody");
        }
    }
    const CommandRun init =
        as_server_user(quoted(bin_ + "/initdb") + " -D " + quoted(directory_ + "/data") +
                       " -A trust -U carrom -E UTF8 --no-sync --no-instructions 2>&1");
    if (init.exit != 0) {
        throw std::runtime_error("initdb failed (" + bin_ + "): " + init.out);
    }
    if (!start()) {
        throw std::runtime_error("pg_ctl start failed: " +
                                 run_command("cat " + quoted(directory_ + "/log")).out);
    }
}

PostgresInstance::~PostgresInstance() {
    if (running_) {
        as_server_user(quoted(bin_ + "/pg_ctl") + " -D " + quoted(directory_ + "/data") +
                       " -m immediate -w stop >/dev/null 2>&1");
    }
    std::error_code ec;
    fs::remove_all(directory_, ec);
}

CommandRun PostgresInstance::as_server_user(const std::string& cmd) const {
    if (::geteuid() != 0) {
        return run_command(cmd);
    }
    return run_command("setpriv --reuid=nobody --regid=nogroup --clear-groups sh -c " +
                       quoted(cmd));
}

bool PostgresInstance::start() {
    // Only the Unix socket in directory_; fsync off: the tests' data need not survive a power
    // loss of the machine.
    const CommandRun ran = as_server_user(
        quoted(bin_ + "/pg_ctl") + " -D " + quoted(directory_ + "/data") + " -l " +
        quoted(directory_ + "/log") + " -o " +
        quoted("-k " + directory_ + " -c listen_addresses= -c fsync=off -c max_connections=200") +
        " -w -t 30 start >/dev/null 2>&1");
    running_ = ran.exit == 0;
    return running_;
}

bool PostgresInstance::stop() {
    const CommandRun ran =
        as_server_user(quoted(bin_ + "/pg_ctl") + " -D " + quoted(directory_ + "/data") +
                       " -m fast -w -t 30 stop >/dev/null 2>&1");
    running_ = ran.exit != 0;
    return ran.exit == 0;
}

std::string PostgresInstance::url(const std::string& database, const std::string& user) const {
    return "postgresql://" + user + "@/" + database + "?host=" + directory_;
}

std::string PostgresInstance::create_database(const std::string& owner) {
    const std::string name = "t" + std::to_string(++databases_);
    const CommandRun ran = sql("postgres", "CREATE DATABASE " + name + " OWNER " + owner);
    if (ran.exit != 0) {
        throw std::runtime_error("cannot create database " + name + ": " + ran.out);
    }
    return name;
}

CommandRun PostgresInstance::sql(const std::string& database, const std::string& statements) const {
    return run_command(quoted(bin_ + "/psql") + " -X -q -A -t -v ON_ERROR_STOP=1 -h " +
                       quoted(directory_) + " -U carrom -d " + quoted(database) + " -c " +
                       quoted(statements) + " 2>&1");
}

} // namespace carrom::test_support
