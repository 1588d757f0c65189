# Thin driver (as neovim does): install what is missing, configure, build, run.
#   make demo   installs, builds (Release) and renders the default head to out/hair.png
#   make test   installs, builds and runs the whole CTest suite on lavapipe
BUILD ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)

# Debian 12 packages the build, the tests and the demo need.
PACKAGES := cmake make g++ pkg-config libvulkan-dev libvulkan-volk-dev glslc libshaderc-dev \
	libglm-dev mesa-vulkan-drivers vulkan-validationlayers libcli11-dev nlohmann-json3-dev \
	libtinyobjloader-dev libpng-dev libgtest-dev

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: deps configure build demo test clean

deps:
	@missing=$$(for p in $(PACKAGES); do \
		dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
		echo "hairpipe: installing missing packages:" $$missing; \
		$(SUDO) apt-get update -q && \
		DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q --no-install-recommends $$missing; \
	fi

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The default head from behind and to the side, where the hair is; 90 settling frames first.
demo: build
	./$(BUILD)/samples/hairpipe render --camera-orbit 145 --out out/hair.png

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 900

clean:
	rm -rf $(BUILD)
