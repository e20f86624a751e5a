# The stand-in for the shader tests when their tools are missing at configure
# time: fails, naming what to install (the suite never skips them).
message(FATAL_ERROR "cannot run the shader tests: missing ${MISSING}; install libvulkan-dev "
                    "mesa-vulkan-drivers glslang-tools and re-run cmake")
