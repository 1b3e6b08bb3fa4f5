# The paper benchmark's first seeds reproduce the committed results trial for trial (success, steps, IoU,
# distance).  Usage: cmake -DTOPONAV=... -DWORK=... -DSOURCE_DIR=... [-DSEEDS=10000-10004] -P paper_trials_test.cmake
if(NOT DEFINED SEEDS)
  set(SEEDS 10000-10004)
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(READ "${SOURCE_DIR}/configs/search/paper.yaml" config)
string(REPLACE "pictures: true" "pictures: false" config "${config}")
file(WRITE "${WORK}/paper.yaml" "${config}")
execute_process(COMMAND ${TOPONAV} bench --config ${WORK}/paper.yaml --seeds ${SEEDS} --out ${WORK}/out --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench exited ${rc}\n${out}\n${err}")
endif()
set(NEW "${WORK}/out/trials.jsonl")
set(REF "${SOURCE_DIR}/results/search_paper/trials.jsonl")
include("${SOURCE_DIR}/tests/experiments/compare_trials.cmake")
