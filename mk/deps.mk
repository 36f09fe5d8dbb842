# Tools ev3lx needs beyond a Debian 12 base with gcc and arm-none-eabi-gcc.
# gcc-multilib and g++-multilib: the 32-bit host configuration (host32, gcc -m32).
# libjson-c-dev: ev3sim run --world's world files (JSON).
# gdb: `ev3sim run --debug`'s check; libmicrohttpd-dev: `ev3sim run --live`'s
# HTTP server; chromium: the live view's browser test (headless).
# `make deps` installs what is missing; `make`/`make test` call it when needed.

DEPS_PACKAGES := g++ gcc-arm-linux-gnueabi g++-arm-linux-gnueabi libc6-dev-armel-cross qemu-user \
	u-boot-tools cloc gnuplot-nox linux-headers-amd64 sparse gcc-arm-none-eabi \
	libnewlib-arm-none-eabi perl cppcheck clang-tidy libpng-dev libgif-dev libjson-c-dev ccache \
	gcc-multilib g++-multilib gdb libmicrohttpd-dev chromium

# tool -> package, checked by `deps-check`
DEPS_TOOLS := g++:g++ arm-linux-gnueabi-gcc:gcc-arm-linux-gnueabi arm-linux-gnueabi-g++:g++-arm-linux-gnueabi qemu-arm:qemu-user \
	addr2line:binutils \
	mkimage:u-boot-tools cloc:cloc gnuplot:gnuplot-nox sparse:sparse \
	arm-none-eabi-gcc:gcc-arm-none-eabi prove:perl cppcheck:cppcheck clang-tidy:clang-tidy ccache:ccache \
	gdb:gdb chromium:chromium

deps_missing = $(strip $(foreach t,$(DEPS_TOOLS),$(if $(shell command -v $(firstword $(subst :, ,$(t))) 2>/dev/null),,$(lastword $(subst :, ,$(t))))) \
	$(if $(wildcard /usr/src/linux-headers-*-amd64/Makefile),,linux-headers-amd64) \
	$(if $(wildcard /usr/arm-linux-gnueabi/lib/libc.so.6),,libc6-dev-armel-cross) \
	$(if $(wildcard /usr/include/png.h /usr/include/libpng/png.h),,libpng-dev) \
	$(if $(wildcard /usr/include/gif_lib.h),,libgif-dev) \
	$(if $(wildcard /usr/include/json-c/json.h),,libjson-c-dev) \
	$(if $(wildcard /usr/include/microhttpd.h),,libmicrohttpd-dev) \
	$(if $(wildcard /usr/lib32/crt1.o),,gcc-multilib) \
	$(if $(wildcard /usr/lib/gcc/x86_64-linux-gnu/*/32/libstdc++.so),,g++-multilib))

.PHONY: deps deps-check
deps:
	@missing="$(deps_missing)"; \
	if [ -z "$$missing" ]; then echo "deps: all tools present"; exit 0; fi; \
	line="apt-get install -y --no-install-recommends $$missing"; \
	if [ "$$(id -u)" != 0 ]; then \
		echo "deps: missing packages; as root run:"; echo "  $$line"; exit 1; \
	fi; \
	echo "deps: $$line"; \
	export DEBIAN_FRONTEND=noninteractive; \
	$$line || { apt-get update && $$line; } || { echo "deps: apt-get failed: $$line"; exit 1; }

deps-check:
	@$(if $(deps_missing),$(MAKE) --no-print-directory deps,true)
