# Start-up time of every penumbra process. Debian's OpenImageIO loads 265 libraries, most
# built with BIND_NOW, and ld.so binds their ~155,000 symbols before main, searching the
# libraries one by one in load order (breadth first from the executable). Most of those
# symbols are a library's references to itself, found only when the search reaches it,
# deep in that order. Naming those libraries in the executable's own DT_NEEDED (they are
# loaded anyway) puts them at the front: about 0.1 s less per process, each render, each
# Slurm task and each of ctest's test processes (docs/performance.md, "Start-up").
# scripts/loader_order.py checks that no symbol moves to or from a strong definition
# (ctest LoaderOrder).

# The list's libraries as OpenImageIO loads them: a soname it does not load is skipped, so
# a different OpenImageIO build never gains a dependency from here.
set(PENUMBRA_LOADER_ORDER "")
find_library(PENUMBRA_OIIO_LIBRARY NAMES OpenImageIO HINTS ${OIIO_LIBRARY_DIRS})
find_program(PENUMBRA_LDD ldd)
if(PENUMBRA_OIIO_LIBRARY AND PENUMBRA_LDD)
    execute_process(COMMAND ${PENUMBRA_LDD} ${PENUMBRA_OIIO_LIBRARY}
                    OUTPUT_VARIABLE _ldd RESULT_VARIABLE _ldd_rc ERROR_QUIET)
    if(_ldd_rc EQUAL 0)
        string(REPLACE "\n" ";" _ldd_lines "${_ldd}")
        foreach(_line IN LISTS _ldd_lines)
            if(_line MATCHES "^[ \t]*([^ \t]+) => ([^ \t]+) ")
                set("_loaded_${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}")
            endif()
        endforeach()
        file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/loader_order.txt _sonames REGEX "^[^#]")
        foreach(_soname IN LISTS _sonames)
            string(STRIP "${_soname}" _soname)
            if(DEFINED "_loaded_${_soname}")
                list(APPEND PENUMBRA_LOADER_ORDER "${_loaded_${_soname}}")
            endif()
        endforeach()
    endif()
endif()
list(LENGTH PENUMBRA_LOADER_ORDER _count)
message(STATUS "Libraries named first for the loader's search: ${_count}")

# Puts the list at the front of target's DT_NEEDED: link options precede the objects and
# libraries on the link line. --no-as-needed: the executable references none of them.
function(penumbra_loader_order target)
    if(PENUMBRA_LOADER_ORDER)
        string(JOIN " " _paths ${PENUMBRA_LOADER_ORDER})
        target_link_options(${target} PRIVATE
                            "SHELL:-Wl,--push-state,--no-as-needed ${_paths} -Wl,--pop-state")
    endif()
endfunction()
