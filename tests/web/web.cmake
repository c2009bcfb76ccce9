# Browser tests of the web client (web/): node drives the system chromium through
# playwright-core (tests/web/package.json, pinned by package-lock.json, installed by `npm ci`
# in scripts/install-deps.sh; nothing is downloaded at test time) against a real carrom-server
# (and carrom-bot). Registered when node and chromium are installed; a test whose
# playwright-core is missing fails with that sentence. The pure modules' unit tests need only node.
# The page's constants are the server's (docs/web.md, "Constants"): needs no node.
add_test(NAME web.physics_config_current
         COMMAND ${CMAKE_COMMAND} -DGENERATOR=$<TARGET_FILE:carrom-web-config>
                 -DCHECKED_IN=${PROJECT_SOURCE_DIR}/web/js/physics_config.js
                 -DOUTPUT=${CMAKE_CURRENT_BINARY_DIR}/physics_config.js
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/web/physics_config_current.cmake)
set_tests_properties(web.physics_config_current PROPERTIES TIMEOUT 30 LABELS web)

find_program(CARROM_NODE NAMES node nodejs)
find_program(CARROM_CHROMIUM NAMES chromium chromium-browser)
if(NOT CARROM_NODE)
    message(STATUS "web tests: node not found, not registered")
    return()
endif()

set(web_dir ${CMAKE_CURRENT_SOURCE_DIR}/web)
add_test(NAME web.unit COMMAND ${CARROM_NODE} ${web_dir}/unit_test.mjs)
set_tests_properties(web.unit PROPERTIES TIMEOUT 60 LABELS web)
add_test(NAME web.golden COMMAND ${CARROM_NODE} ${web_dir}/golden_test.mjs)
set_tests_properties(web.golden PROPERTIES TIMEOUT 60 LABELS web)
add_test(NAME web.emotes_unit COMMAND ${CARROM_NODE} ${web_dir}/emotes_unit.mjs)
set_tests_properties(web.emotes_unit PROPERTIES TIMEOUT 60 LABELS web)
add_test(NAME web.doubles_unit COMMAND ${CARROM_NODE} ${web_dir}/doubles_test.mjs)
set_tests_properties(web.doubles_unit PROPERTIES TIMEOUT 60 LABELS web)
add_test(NAME web.texts COMMAND ${CARROM_NODE} ${web_dir}/texts_test.mjs)
set_tests_properties(web.texts PROPERTIES TIMEOUT 60 LABELS web)
# The session's decisions against tests/golden/session/*.json (net::SessionCore's cases).
add_test(NAME web.session COMMAND ${CARROM_NODE} ${web_dir}/session_test.mjs)
set_tests_properties(web.session PROPERTIES TIMEOUT 60 LABELS web)
add_test(NAME web.identity COMMAND ${CARROM_NODE} ${web_dir}/identity_test.mjs)
set_tests_properties(web.identity PROPERTIES TIMEOUT 60 LABELS web)
add_test(NAME web.ratings_unit COMMAND ${CARROM_NODE} ${web_dir}/ratings_unit.mjs)
set_tests_properties(web.ratings_unit PROPERTIES TIMEOUT 60 LABELS web)

if(NOT CARROM_CHROMIUM OR NOT TARGET carrom-server OR NOT TARGET carrom-bot)
    message(STATUS "web tests: chromium, carrom-server or carrom-bot missing, browser tests not registered")
    return()
endif()

# The page's engine (wasm/CMakeLists.txt): without it the page runs without prediction and
# replays; CARROM_WEB_ENGINE tells the tests which page they get, and the replay test needs it.
set(web_tests two_pages_match page_vs_bot touch_phone reload_resume lobby_paths doubles_pages https_page
              redirect_page
              identity_page first_game_ui texts_pages emotes_pages)
if(CARROM_WEB_WASM)
    list(APPEND web_tests replay_page aim_assist_page)
endif()
# The ratings' page test writes its players' ratings into the store with the sqlite3 program.
find_program(CARROM_SQLITE3 NAMES sqlite3)
if(CARROM_SQLITE3)
    list(APPEND web_tests ratings_page)
else()
    message(STATUS "web tests: sqlite3 not found, web.ratings_page not registered")
endif()
foreach(test ${web_tests})
    add_test(NAME web.${test} COMMAND ${CARROM_NODE} ${web_dir}/${test}.mjs)
    set_tests_properties(web.${test} PROPERTIES
        TIMEOUT 200
        LABELS web
        # One browser at a time: each starts several pages, and timings stay honest.
        RESOURCE_LOCK chromium
        ENVIRONMENT "CARROM_SERVER=$<TARGET_FILE:carrom-server>;CARROM_BOT=$<TARGET_FILE:carrom-bot>;CARROM_CHROMIUM=${CARROM_CHROMIUM};CARROM_SQLITE3=${CARROM_SQLITE3};CARROM_WEB_ENGINE=$<IF:$<BOOL:${CARROM_WEB_WASM}>,1,0>")
endforeach()

# A page against carrom-client (the desktop client, `--autoplay`, under `xvfb-run -a` when the
# test's environment has no DISPLAY): the same final state on both sides.
if(TARGET carrom-client)
    add_test(NAME web.client_match COMMAND ${CARROM_NODE} ${web_dir}/client_match.mjs)
    set_tests_properties(web.client_match PROPERTIES
        TIMEOUT 100
        LABELS web
        RESOURCE_LOCK chromium
        ENVIRONMENT "CARROM_SERVER=$<TARGET_FILE:carrom-server>;CARROM_CLIENT=$<TARGET_FILE:carrom-client>;CARROM_CHROMIUM=${CARROM_CHROMIUM}")
endif()
