# GMP's C and C++ libraries as the imported targets drange::gmp and drange::gmpxx (gmpxx links
# gmp after it). Included by the build and by the installed drangeConfig.cmake: drange is a
# static library, so a program that links it links GMP too, and the installed package looks
# GMP up on the consumer's machine rather than recording where it was on the build machine.
# Leaves the targets undefined when either library is missing; the caller reports it.
find_library(GMP_LIBRARY gmp)
find_library(GMPXX_LIBRARY gmpxx)
if(GMP_LIBRARY AND GMPXX_LIBRARY AND NOT TARGET drange::gmp)
  add_library(drange::gmp UNKNOWN IMPORTED)
  set_target_properties(drange::gmp PROPERTIES IMPORTED_LOCATION "${GMP_LIBRARY}")
  add_library(drange::gmpxx UNKNOWN IMPORTED)
  set_target_properties(drange::gmpxx PROPERTIES IMPORTED_LOCATION "${GMPXX_LIBRARY}"
                        INTERFACE_LINK_LIBRARIES drange::gmp)
endif()
