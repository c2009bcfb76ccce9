# web/js/physics_config.js must be what carrom-web-config writes from common's config today (the
# server embeds the generated module; node's tests and --web-root read the copy under web/). Run as
#   cmake -DGENERATOR=<carrom-web-config> -DCHECKED_IN=<web/js/physics_config.js> -DOUTPUT=<tmp> -P physics_config_current.cmake
execute_process(COMMAND "${GENERATOR}" --out "${OUTPUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "carrom-web-config failed (${rc})")
endif()
file(READ "${CHECKED_IN}" checked_in)
file(READ "${OUTPUT}" generated)
if(NOT checked_in STREQUAL generated)
    message(FATAL_ERROR "${CHECKED_IN} differs from common's config; regenerate it with\n"
                        "  build/test/tools/carrom-web-config --out web/js/physics_config.js")
endif()
message(STATUS "web/js/physics_config.js is current")
