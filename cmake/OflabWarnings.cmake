# oflab_target_defaults(<target>): warnings and, with OFLAB_SANITIZE, ASan + UBSan.
function(oflab_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(OFLAB_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                                             -fno-sanitize-recover=all -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# oflab_test_target_defaults(<target>): the defaults of a test program. Its own files are
# compiled at -O1 in the optimised builds: optimising test code at -O3 took about 40 % of its
# compile time for nothing the tests measure (the libraries they test keep -O3, and GCC's -O
# levels give the same floating-point results: ISO C++ mode, no contraction). With
# OFLAB_SANITIZE the program links the sanitizers' runtime, so the libraries it tests run
# instrumented and every allocation is watched (leaks included), but its own files are not
# instrumented: that took half of their compile time, for errors in test code only.
function(oflab_test_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(OFLAB_SANITIZE)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release,RelWithDebInfo,MinSizeRel>:-O1>)
endfunction()
