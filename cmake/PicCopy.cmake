# Position-independent copies of the renderer's static libraries, for the Python module.
# A shared object cannot hold the default (PIE) objects: their thread_local variables use
# the local-exec model, which only an executable may. Copying keeps the CLI's own code as it
# is (no GOT or __tls_get_addr in its render loop); the copies compile the same sources with
# the same flags plus -fPIC, so their images are the same bit for bit (no FMA contraction
# without -march; the module's test checks it against the CLI's EXR).

# penumbra_pic_copy(LIB): LIB_pic, a PIC copy of static library LIB with its sources,
# include directories, definitions, options and links; links to other copied libraries
# (copy them first) go to their copies.
function(penumbra_pic_copy lib)
    get_target_property(dir ${lib} SOURCE_DIR)
    get_target_property(bin ${lib} BINARY_DIR)
    get_target_property(sources ${lib} SOURCES)
    set(absolute "")
    foreach(s IN LISTS sources)
        # A generated header (materials' albedo table) stays with its library, which builds
        # it: the copy depends on the original below.
        if(s MATCHES "\\.inc$")
            continue()
        endif()
        if(NOT IS_ABSOLUTE "${s}")
            set(s "${dir}/${s}")
        endif()
        list(APPEND absolute "${s}")
    endforeach()
    add_library(${lib}_pic STATIC EXCLUDE_FROM_ALL ${absolute})
    set_target_properties(${lib}_pic PROPERTIES POSITION_INDEPENDENT_CODE ON)
    add_dependencies(${lib}_pic ${lib})
    foreach(prop INCLUDE_DIRECTORIES COMPILE_DEFINITIONS COMPILE_OPTIONS COMPILE_FEATURES
                 INTERFACE_INCLUDE_DIRECTORIES INTERFACE_COMPILE_DEFINITIONS
                 INTERFACE_COMPILE_OPTIONS INTERFACE_COMPILE_FEATURES)
        get_target_property(value ${lib} ${prop})
        if(value)
            set_target_properties(${lib}_pic PROPERTIES ${prop} "${value}")
        endif()
    endforeach()
    foreach(prop LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
        get_target_property(value ${lib} ${prop})
        if(NOT value)
            continue()
        endif()
        set(mapped "")
        foreach(item IN LISTS value)
            # INTERFACE_LINK_LIBRARIES wraps a private dependency as $<LINK_ONLY:name>.
            # (${CMAKE_MATCH_n} expands before if() evaluates: test the target after.)
            if(item MATCHES "^(\\$<LINK_ONLY:)?(penumbra_[a-z_]+)(>)?$")
                if(TARGET ${CMAKE_MATCH_2}_pic)
                    set(item "${CMAKE_MATCH_1}${CMAKE_MATCH_2}_pic${CMAKE_MATCH_3}")
                endif()
            endif()
            list(APPEND mapped "${item}")
        endforeach()
        set_target_properties(${lib}_pic PROPERTIES ${prop} "${mapped}")
    endforeach()
endfunction()
