# End-to-end checks of the toponav CLI.  Usage: cmake -DTOPONAV=... -DWORK=... -DSOURCE_DIR=... -P cli_test.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

function(run expect_rc)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "expected exit ${expect_rc}, got ${rc}: ${ARGN}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(OUT "${out}" PARENT_SCOPE)
  set(ERR "${err}" PARENT_SCOPE)
endfunction()

function(expect_contains text what)
  string(FIND "${text}" "${what}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "expected to find '${what}' in:\n${text}")
  endif()
endfunction()

# help for every subcommand
run(0 ${TOPONAV} --help)
expect_contains("${OUT}" "observe")
foreach(sub world observe render demo info)
  run(0 ${TOPONAV} ${sub} --help)
  expect_contains("${OUT}" "--")
endforeach()

# world: JSON + PNG; same seed gives identical bytes
run(0 ${TOPONAV} world --kind labyrinth --seed 7 --out ${WORK}/a)
run(0 ${TOPONAV} world --kind labyrinth --seed 7 --out ${WORK}/b --no-png)
file(SHA256 ${WORK}/a/world.json ha)
file(SHA256 ${WORK}/b/world.json hb)
if(NOT ha STREQUAL hb)
  message(FATAL_ERROR "same seed gave different world.json")
endif()
if(NOT EXISTS ${WORK}/a/world.png OR EXISTS ${WORK}/b/world.png)
  message(FATAL_ERROR "--no-png not honoured or picture missing")
endif()

# several seeds with checks
run(0 ${TOPONAV} world --kind guided_maze --seeds 3-5 --out ${WORK}/m --no-png --check)
expect_contains("${OUT}" "3 worlds")
if(NOT EXISTS ${WORK}/m/guided_maze_s5.json)
  message(FATAL_ERROR "missing guided_maze_s5.json")
endif()

# observe from a world file prints JSON with labels and the visibility polygon
run(0 ${TOPONAV} observe --world ${WORK}/a/world.json --png ${WORK}/obs.png)
expect_contains("${OUT}" "visible_vertices")
expect_contains("${OUT}" "visibility_polygon")
expect_contains("${OUT}" "\"label\"")
run(0 ${TOPONAV} observe --kind office_park --seed 2 --pose 0,0,0)

# a hand-written floor plan works where a generated world does
file(WRITE ${WORK}/plan.json [=[{"boundary": [[0,0],[40,0],[40,30],[0,30]], "obstacles": [[[10,10],[20,10],[20,20],[10,20]]], "start": {"x": 5, "y": 5, "yaw": 0}, "goal": [35, 25]}]=])
run(0 ${TOPONAV} observe --world ${WORK}/plan.json --pose 5,5,0)
expect_contains("${OUT}" "corner")
run(0 ${TOPONAV} world --world ${WORK}/plan.json --out ${WORK}/plan)

# render: a panorama with depth and ids, and a contact sheet
run(0 ${TOPONAV} render --kind guided_maze --seed 4 --out ${WORK}/pano.png --depth ${WORK}/depth.png --ids ${WORK}/ids.txt)
expect_contains("${OUT}" "512x128")
foreach(f pano.png depth.png ids.txt)
  if(NOT EXISTS ${WORK}/${f})
    message(FATAL_ERROR "render did not write ${f}")
  endif()
endforeach()
run(0 ${TOPONAV} render --world ${WORK}/plan.json --poses 2 --out ${WORK}/sheet.png)
expect_contains("${OUT}" "2 panoramas")
file(WRITE ${WORK}/bad_render.yaml "render:\n  width: 510\n")
run(2 ${TOPONAV} render --kind labyrinth --config ${WORK}/bad_render.yaml --out ${WORK}/x.png)
expect_contains("${ERR}" "render.width")

# errors name the file and the problem
file(WRITE ${WORK}/bad.json [=[{"obstacles": [[[0,0],[2,2],[2,0],[0,2]]], "start": {"x": -3, "y": -3}, "goal": [5,5]}]=])
run(1 ${TOPONAV} observe --world ${WORK}/bad.json)
expect_contains("${ERR}" "bad.json")
expect_contains("${ERR}" "self-intersecting")
file(WRITE ${WORK}/bad.yaml "worlds:\n  labyrinth:\n    num_rooms: 40\n")
run(2 ${TOPONAV} world --kind labyrinth --config ${WORK}/bad.yaml --out ${WORK}/c)
expect_contains("${ERR}" "bad.yaml")
expect_contains("${ERR}" "worlds.labyrinth.num_rooms")
expect_contains("${ERR}" "40")
run(2 ${TOPONAV} observe --kind labyrinth --pose 1,2)
expect_contains("${ERR}" "--pose")
run(2 ${TOPONAV} world --kind castle)
expect_contains("${ERR}" "castle")
message(STATUS "CLI checks passed")
