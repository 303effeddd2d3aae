# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# The stages of lib/isovdb/ and the stages each one may use: one DAG, lowest
# first. lib/ builds each stage as an object library; a stage's tests link the
# stage with exactly what it declares here (isovdb_link_stages), and the test
# Layers.IncludesFollowTheDeclaredStages (cmake/CheckLayers.cmake) fails on an
# include of a stage that is not declared. The headers at lib/isovdb/ itself
# (errors.h, progress.h, bit_interleave.h, split_mix.h) are below every stage.
set(ISOVDB_STAGES mesh io cell octree volume store contour stitch morph reservoir pipeline)
set(ISOVDB_USES_mesh "")                          # indexed mesh, sinks, welding, validation
set(ISOVDB_USES_io mesh)                          # readers (SliceStream), mesh files, atomic files
set(ISOVDB_USES_cell "")                          # one cell: samples block, DMC table, crossings, QEF, dual vertex
set(ISOVDB_USES_octree cell)                      # linear octree of a meta-cell, criteria
set(ISOVDB_USES_volume io cell)                   # sparse grids, ingest, distance field, meta-cell blocks
set(ISOVDB_USES_store io volume)                  # .vdb files, dense export, SEG-Y survey metadata
set(ISOVDB_USES_contour cell octree volume mesh)  # regular and adaptive contouring, OpenVDB's mesher
set(ISOVDB_USES_stitch contour octree cell mesh)  # seams between meta-cells
set(ISOVDB_USES_morph io volume)                  # slice metamorphosis
set(ISOVDB_USES_reservoir mesh)                   # corner-point grids
set(ISOVDB_USES_pipeline contour io mesh octree reservoir stitch store volume morph cell)

# isovdb_stage_closure(<out> <stage>...): the stages and everything they use.
function(isovdb_stage_closure out)
  set(result "")
  set(pending ${ARGN})
  while(pending)
    list(POP_FRONT pending stage)
    if(NOT stage IN_LIST result)
      list(APPEND result ${stage})
      list(APPEND pending ${ISOVDB_USES_${stage}})
    endif()
  endwhile()
  set(${out} ${result} PARENT_SCOPE)
endfunction()
