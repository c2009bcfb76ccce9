# Replay of the committed fuzz corpora (tests/fuzz/corpus/<target>/) through the libFuzzer
# harnesses, built with the project's compiler and flags and run by ctest: one executable per
# target, since each harness defines LLVMFuzzerTestOneInput. Fuzzing itself needs clang and
# libFuzzer and is done by scripts/fuzz.sh, outside CMake. Include from tests/CMakeLists.txt:
#   include(${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz.cmake)
set(carrom_fuzz_dir ${CMAKE_CURRENT_SOURCE_DIR}/fuzz)

function(carrom_add_fuzz_replay target)
    add_executable(carrom_fuzz_replay_${target} ${carrom_fuzz_dir}/replay_main.cpp
                                                ${carrom_fuzz_dir}/fail.cpp ${ARGN})
    target_compile_definitions(carrom_fuzz_replay_${target} PRIVATE
        CARROM_FUZZ_CORPUS="${carrom_fuzz_dir}/corpus/${target}")
    target_link_libraries(carrom_fuzz_replay_${target} PRIVATE carrom_warnings)
    add_test(NAME fuzz_replay_${target} COMMAND carrom_fuzz_replay_${target})
    set_tests_properties(fuzz_replay_${target} PROPERTIES TIMEOUT 120 LABELS fuzz)
endfunction()

carrom_add_fuzz_replay(codec ${carrom_fuzz_dir}/codec_target.cpp ${carrom_fuzz_dir}/codec_fuzz.cpp
                             ${carrom_fuzz_dir}/scene_fuzz.cpp)
target_link_libraries(carrom_fuzz_replay_codec PRIVATE carrom_proto)
if(TARGET carrom_server_lib)
    carrom_add_fuzz_replay(room ${carrom_fuzz_dir}/room_fuzz.cpp)
    target_link_libraries(carrom_fuzz_replay_room PRIVATE carrom_server_lib)
endif()

if(CARROM_FUZZ)
    function(carrom_add_fuzzer target)
        add_executable(carrom_${target}_fuzzer ${carrom_fuzz_dir}/fail.cpp ${ARGN})
        target_link_options(carrom_${target}_fuzzer PRIVATE -fsanitize=fuzzer)
    endfunction()
    carrom_add_fuzzer(codec ${carrom_fuzz_dir}/codec_target.cpp ${carrom_fuzz_dir}/codec_fuzz.cpp
                            ${carrom_fuzz_dir}/scene_fuzz.cpp)
    target_link_libraries(carrom_codec_fuzzer PRIVATE carrom_proto)
    if(TARGET carrom_server_lib)
        carrom_add_fuzzer(room ${carrom_fuzz_dir}/room_fuzz.cpp)
        target_link_libraries(carrom_room_fuzzer PRIVATE carrom_server_lib)
    endif()
endif()
