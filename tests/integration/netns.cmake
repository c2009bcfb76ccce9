# The two-machine test: carrom-server and two carrom-bot in two network namespaces joined by a
# veth pair (scripts/netns_match_test.sh). Needs root and iproute2; without them it fails and
# says why (it is never skipped). Include from tests/CMakeLists.txt:
#   include(${CMAKE_CURRENT_SOURCE_DIR}/integration/netns.cmake)
add_test(NAME netns_match
         COMMAND ${PROJECT_SOURCE_DIR}/scripts/netns_match_test.sh
                 $<TARGET_FILE:carrom-server> $<TARGET_FILE:carrom-bot>)
# RUN_SERIAL: it creates network namespaces and must not compete for the cores with
# timing-sensitive tests.
set_tests_properties(netns_match PROPERTIES TIMEOUT 240 RUN_SERIAL TRUE LABELS "netns;root")
