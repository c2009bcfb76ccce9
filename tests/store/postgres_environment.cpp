// The store tests' PostgreSQL server: one per test binary, started when a test first needs it
// (so a binary that runs only SQLite tests starts none), stopped and removed when the binary's
// tests end.

#include "store_support.hpp"

#include <memory>

namespace carrom::store::test {
namespace {

std::unique_ptr<test_support::PostgresInstance>& postgres_slot() {
    static std::unique_ptr<test_support::PostgresInstance> server;
    return server;
}

class PostgresEnvironment : public ::testing::Environment {
public:
    void TearDown() override { postgres_slot().reset(); }
};

[[maybe_unused]] const auto* const kPostgresEnvironment =
    ::testing::AddGlobalTestEnvironment(new PostgresEnvironment);

} // namespace

test_support::PostgresInstance& postgres_server() {
    auto& server = postgres_slot();
    if (!server) {
        server = std::make_unique<test_support::PostgresInstance>();
    }
    return *server;
}

} // namespace carrom::store::test
