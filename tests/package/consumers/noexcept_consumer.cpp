// Built with -fno-exceptions: hairpipe's failures arrive as values with messages naming the problem.
#include <cstdio>
#include <string>

#include <hairpipe/hairpipe.h>

namespace {
int failures = 0;
void expect(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok) ++failures;
}
bool contains(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }
}  // namespace

int main() {
  hairpipe::AssetSource source;
  source.path = "/nonexistent/groom.hair";
  const hairpipe::Result<hairpipe::Asset> missing = hairpipe::loadAsset(source);
  expect(!missing && contains(missing.message(), "hairpipe::loadAsset") && contains(missing.message(), "/nonexistent/groom.hair"),
         "loadAsset of a missing file: " + missing.message());
  source.path = "groom.png";
  const hairpipe::Result<hairpipe::Asset> wrongKind = hairpipe::loadAsset(source);
  expect(!wrongKind && contains(wrongKind.message(), ".hair, .tfx or .obj"), "loadAsset of another format: " + wrongKind.message());

  hairpipe::HeadlessOptions headless;
  headless.validation = true;
  hairpipe::Result<hairpipe::Context> ctx = hairpipe::Context::createHeadless(headless);
  expect(ctx.ok(), "a headless context: " + (ctx ? std::string(ctx->deviceName()) : ctx.message()));
  if (!ctx) return 1;
  hairpipe::RendererSettings settings;
  settings.framesInFlight = 0;
  const hairpipe::Result<hairpipe::Renderer> none = hairpipe::Renderer::create(ctx.value(), settings);
  expect(!none && contains(none.message(), "hairpipe::Renderer::create") && contains(none.message(), "framesInFlight"),
         "a renderer with no frame in flight: " + none.message());
  hairpipe::Camera camera;
  camera.eye = camera.target;
  const hairpipe::Result<hairpipe::View> view = hairpipe::makeView(camera, {64, 64});
  expect(!view && contains(view.message(), "eye is at the target"), "a degenerate camera: " + view.message());
  const hairpipe::Status idle = ctx->waitIdle();
  expect(idle.ok(), "waitIdle on a headless device");
  const hairpipe::Result<std::vector<std::string>> messages = ctx->validationMessages();
  expect(messages.ok() && messages.value().empty(), "no validation message");
  return failures == 0 ? 0 : 1;
}
