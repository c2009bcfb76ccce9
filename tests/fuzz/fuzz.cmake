# The fuzz targets (tests/fuzz/). Each target's harness defines LLVMFuzzerTestOneInput, so each
# gets its own executables:
# - carrom_fuzz_replay_<target>, built with the project's compiler and flags: replays the
#   committed corpus (tests/fuzz/corpus/<target>/) as the ctest test fuzz_replay_<target>;
# - with CARROM_FUZZ=ON (clang; scripts/fuzz.sh configures build/fuzz so), also
#   carrom_<target>_fuzzer, the libFuzzer executable.
# Include from tests/CMakeLists.txt: include(${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz.cmake)
set(carrom_fuzz_dir ${CMAKE_CURRENT_SOURCE_DIR}/fuzz)

# A fuzz target: its harness sources (ARGN) and the library they drive.
function(carrom_add_fuzz_target target library)
    set(sources ${carrom_fuzz_dir}/fail.cpp ${ARGN})
    set(replay carrom_fuzz_replay_${target})
    add_executable(${replay} ${carrom_fuzz_dir}/replay_main.cpp ${sources})
    target_compile_definitions(${replay} PRIVATE
        CARROM_FUZZ_CORPUS="${carrom_fuzz_dir}/corpus/${target}")
    target_link_libraries(${replay} PRIVATE ${library} carrom_warnings)
    add_test(NAME fuzz_replay_${target} COMMAND ${replay})
    set_tests_properties(fuzz_replay_${target} PROPERTIES TIMEOUT 120 LABELS fuzz)
    if(CARROM_FUZZ)
        add_executable(carrom_${target}_fuzzer ${sources})
        target_link_libraries(carrom_${target}_fuzzer PRIVATE ${library})
        target_link_options(carrom_${target}_fuzzer PRIVATE -fsanitize=fuzzer)
    endif()
endfunction()

carrom_add_fuzz_target(codec carrom_proto ${carrom_fuzz_dir}/codec_target.cpp
                       ${carrom_fuzz_dir}/codec_fuzz.cpp ${carrom_fuzz_dir}/scene_fuzz.cpp)
carrom_add_fuzz_target(room carrom_room ${carrom_fuzz_dir}/room_fuzz.cpp)
