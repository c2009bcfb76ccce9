# The deployment files (docs/deploy.md): HAProxy's configuration checked by `haproxy -c` (skipped,
# exit 77, when haproxy is not installed), the compose file and the Kubernetes manifests parsed
# and checked (python3-yaml), and scripts/cluster.sh --check: PostgreSQL, three carrom-server
# instances and HAProxy on this machine, a bot match through the front (skipped, exit 77, when
# haproxy or PostgreSQL is not installed). Include from tests/CMakeLists.txt:
#   include(${CMAKE_CURRENT_SOURCE_DIR}/deploy/deploy.cmake)
find_program(CARROM_PYTHON3 NAMES python3)
if(NOT CARROM_PYTHON3)
    message(STATUS "deploy tests: python3 not found, not registered")
    return()
endif()
foreach(case haproxy compose k8s)
    add_test(NAME deploy.${case}
             COMMAND ${CARROM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/deploy/deploy_files_test.py
                     ${PROJECT_SOURCE_DIR} ${case})
    set_tests_properties(deploy.${case} PROPERTIES TIMEOUT 60 LABELS deploy SKIP_RETURN_CODE 77)
endforeach()
if(TARGET carrom-server AND TARGET carrom-bot)
    add_test(NAME deploy.cluster_check
             COMMAND ${PROJECT_SOURCE_DIR}/scripts/cluster.sh --check
                     --server $<TARGET_FILE:carrom-server> --bot $<TARGET_FILE:carrom-bot>)
    set_tests_properties(deploy.cluster_check PROPERTIES TIMEOUT 90 LABELS deploy
                                                         SKIP_RETURN_CODE 77)
endif()
