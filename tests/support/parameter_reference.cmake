# The parameter reference doc/parameters.md is `wearlink --print-parameters` (every
# declared entry with its documentation, unit and default) under a fixed header. This
# script checks that the file is that text, or with -DUPDATE=1 writes it:
#   cmake -DWEARLINK=build/wearlink -DREFERENCE=doc/parameters.md [-DUPDATE=1] \
#         -P tests/support/parameter_reference.cmake
execute_process(COMMAND ${WEARLINK} --print-parameters
                RESULT_VARIABLE status
                OUTPUT_VARIABLE listing
                ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "wearlink --print-parameters failed (${status}): ${err}")
endif()
set(header "# Parameter reference

Every entry a scene file can set, with what it means, its unit, its allowed values and
its default, as `wearlink --print-parameters` prints it. A subsection written
`<name>` (`Body <name>`, `Joint <name>`) is repeated once per body or joint the
scene's `Mechanism` section lists; the plugin subsections of a joint (its contact law,
friction law and pressure model) are read only for the plugins it chooses.
`wearlink --print-parameters SCENE.prm` prints the same with that scene's values.

This file is generated; after a change of a declaration, write it again with

```sh
cmake -DWEARLINK=build/wearlink -DREFERENCE=doc/parameters.md -DUPDATE=1 -P tests/support/parameter_reference.cmake
```

and the test `doc.parameter_reference` checks that it is current.

```
")
set(expected "${header}${listing}```\n")
if(UPDATE)
  file(WRITE "${REFERENCE}" "${expected}")
  message("wrote ${REFERENCE}")
  return()
endif()
if(NOT EXISTS "${REFERENCE}")
  message(FATAL_ERROR "${REFERENCE} is missing; write it with -DUPDATE=1 (see the comment of this script)")
endif()
file(READ "${REFERENCE}" actual)
if(NOT actual STREQUAL expected)
  message(FATAL_ERROR "${REFERENCE} is stale: it differs from `wearlink --print-parameters`. Write it again with\n"
                      "  cmake -DWEARLINK=build/wearlink -DREFERENCE=doc/parameters.md -DUPDATE=1 -P tests/support/parameter_reference.cmake")
endif()
