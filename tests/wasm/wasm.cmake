# The WebAssembly engine against the native one (docs/web.md, "Determinism across builds"):
# registered when emscripten built carrom_engine.wasm (wasm/CMakeLists.txt) and node is found.
find_program(CARROM_NODE NAMES node nodejs)
if(NOT CARROM_WEB_WASM OR NOT CARROM_NODE)
    message(STATUS "wasm tests: no carrom_engine.wasm or no node, not registered")
    return()
endif()
add_test(NAME wasm.determinism
         COMMAND ${CARROM_NODE} ${CMAKE_CURRENT_SOURCE_DIR}/wasm/determinism_test.mjs 1000)
set_tests_properties(wasm.determinism PROPERTIES
    TIMEOUT 120
    LABELS web
    ENVIRONMENT "CARROM_ENGINE_CASES=$<TARGET_FILE:carrom-engine-cases>;CARROM_ENGINE_WASM=${CARROM_WEB_WASM}")
add_test(NAME wasm.prediction COMMAND ${CARROM_NODE} ${CMAKE_CURRENT_SOURCE_DIR}/wasm/prediction_test.mjs)
set_tests_properties(wasm.prediction PROPERTIES
    TIMEOUT 60
    LABELS web
    ENVIRONMENT "CARROM_ENGINE_CASES=$<TARGET_FILE:carrom-engine-cases>;CARROM_ENGINE_WASM=${CARROM_WEB_WASM}")
add_test(NAME wasm.aim_assist COMMAND ${CARROM_NODE} ${CMAKE_CURRENT_SOURCE_DIR}/wasm/aim_assist_test.mjs)
set_tests_properties(wasm.aim_assist PROPERTIES
    TIMEOUT 60
    LABELS web
    ENVIRONMENT "CARROM_ENGINE_CASES=$<TARGET_FILE:carrom-engine-cases>;CARROM_ENGINE_WASM=${CARROM_WEB_WASM}")
