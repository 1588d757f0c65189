# Thin driver (as neovim does): install what is missing, configure, build, run.
#   make demo   installs, builds (Release) and renders the default head to out/hair.png (and front,
#               side and back views to out/), lit by the sun and the studio environment; writes nothing
#               outside out/
#   make pictures  re-renders the README's pictures (docs/images: front, back, side with and without the groom,
#                  with the hair grid, curly and clumped sides, blonde, a shaking head's sheet)
#   make api-docs  the API reference of the public headers (doxygen, warnings as errors) in out/api/
#   make test   installs, builds and runs the whole CTest suite on lavapipe
#   make fuzz   builds the libFuzzer targets (clang, ASan+UBSan) and runs each for FUZZ_SECONDS
#   make test-asan  builds everything with ASan+UBSan (clang) and runs the sanitizer suite
BUILD ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
# ctest runs one test more than there are cores: many tests spend part of their time on one thread (lavapipe's
# shader compiles, the CPU path tracer, files), so the extra one fills the idle core (the suite on the 2-core
# VM: 440 s at -j2, 406 s at -j3).
TEST_JOBS ?= $(shell echo $$(( $(JOBS) + 1 )))
SAN_BUILD ?= build-asan
FUZZ_SECONDS ?= 60
# The look of the demo and the README's pictures: the sun plus the built-in studio environment
# (docs/SHADING.md "Environment"); the library and `hairpipe render` default to the sun and a uniform sky.
LOOK ?= --environment studio

# Debian 12 packages the build, the tests and the demo need.
PACKAGES := cmake make g++ pkg-config libvulkan-dev libvulkan-volk-dev glslc libshaderc-dev \
	libglm-dev mesa-vulkan-drivers vulkan-validationlayers libcli11-dev nlohmann-json3-dev \
	libtinyobjloader-dev libtinygltf-dev libpng-dev libgtest-dev libembree-dev clang-14 libclang-rt-14-dev \
	libglfw3-dev libimgui-dev libstb-dev xvfb doxygen spirv-tools

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: deps configure build demo pictures api-docs test clean configure-asan fuzz test-asan

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

# The default head from behind and to the side, where the hair is; 90 settling frames first; then the
# front, side and back views beside it.
demo: build
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 145 --out out/hair.png
	for orbit in 0 90 180; do ./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit $$orbit --width 480 \
		--height 360 --out out/head_$$orbit.png || exit 1; done

# The README's pictures: front and back (small, so the PNGs stay well under 300 KB) and a contact sheet of
# a shaking head (--sequence; its frames go to out/sequence).
pictures: build
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 0 --width 480 --height 360 --out docs/images/head_front.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 180 --width 480 --height 360 --out docs/images/head_back.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 90 --width 480 --height 360 --curl 0.006,40,0.4 \
		--out docs/images/head_side_curly.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 90 --width 480 --height 360 --clump 1,0.9,1.5 \
		--out docs/images/head_side_clumped.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 90 --width 480 --height 360 \
		--out docs/images/head_side.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 90 --width 480 --height 360 --no-groom \
		--out docs/images/head_side_plain.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 90 --width 480 --height 360 --volume 0.6 --friction 0.1 \
		--out docs/images/head_side_volume.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 145 --width 480 --height 360 --color 0.8,0.65,0.45 \
		--out docs/images/head_blonde.png
	./$(BUILD)/samples/hairpipe render $(LOOK) --camera-orbit 150 --width 240 --height 180 --animate shake --fps 60 \
		--frames 48 --sequence out/sequence --contact-sheet docs/images/shake_contact_sheet.png

# The public API's reference from engine/include/hairpipe (docs/Doxyfile); any doxygen warning fails it.
api-docs: deps
	mkdir -p out/api && doxygen docs/Doxyfile

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(TEST_JOBS) --timeout 900

# One clang build with AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer instrumentation
# serves both the fuzzers and the sanitizer test run. SAN_SCOPE=host (what CI runs) builds and tests
# only the device-free code: the asset parsers, shading, and the parser fuzzers; SAN_SCOPE=all adds
# the Vulkan library, the tool, every suite and the CLI fuzzer (a second full build: too slow for CI).
SAN_SCOPE ?= all
HOST_FUZZERS := fuzz_hair fuzz_tfx fuzz_tfxbone fuzz_gltf fuzz_ply fuzz_tfxmesh fuzz_obj fuzz_scene fuzz_brdf_csv fuzz_pfm \
	fuzz_albedo_obj fuzz_hdr
ifeq ($(SAN_SCOPE),host)
SAN_TARGETS := hair_tests shading_tests $(HOST_FUZZERS)
SAN_LABEL := -L host
SAN_PRELOAD :=
FUZZERS ?= $(HOST_FUZZERS)
else
SAN_TARGETS := all hairpipe_fuzzers
SAN_LABEL :=
# Keeps the Vulkan driver and layer libraries loaded to each process's end so that their leaks can be
# suppressed by name (tests/sanitizer/keep_suppressed_libraries.c). Not for the host scope: no Vulkan
# there, and loading the driver costs ~0.25 s a process.
SAN_PRELOAD := LD_PRELOAD=$(abspath $(SAN_BUILD))/libkeep_suppressed_libraries.so
FUZZERS ?= $(HOST_FUZZERS) fuzz_cli
endif

# Line tables only, not full debug information: the sanitizers' reports still name file and line, and the
# build takes ~6% less (133 -> 125 s for CI's host scope on the 2-core VM).
SAN_FLAGS := -O2 -gline-tables-only -DNDEBUG

configure-asan: deps
	CC=clang-14 CXX=clang++-14 cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHAIRPIPE_FUZZ=ON \
		"-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$(SAN_FLAGS)" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$(SAN_FLAGS)"

fuzz: configure-asan
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(FUZZERS)
	tests/fuzz/run_fuzzers.sh $(SAN_BUILD) $(FUZZ_SECONDS) $(FUZZERS)

test-asan: configure-asan
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(SAN_TARGETS)
	cd $(SAN_BUILD) && $(SAN_PRELOAD) \
		ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
		LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizer/lsan.supp:print_suppressions=0 \
		UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
		ctest --output-on-failure -j $(JOBS) --timeout 900 $(SAN_LABEL)

clean:
	rm -rf $(BUILD) $(SAN_BUILD)
