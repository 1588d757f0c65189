// `hairpipe compare`: PSNR, SSIM and mean-luminance ratio of an image against a reference over a
// mask (samples/tools/image_compare.h), e.g. an exported real-time frame against `hairpipe reference`:
//   hairpipe compare --image DIR/realtime.pfm --reference ref.pfm --mask DIR/realtime_hair_alpha.pfm
#include <iostream>

#include <nlohmann/json.hpp>

#include "samples/cli/command.h"
#include "samples/tools/image_compare.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_compare {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct CompareOptions {
  std::string image, reference, mask;
  float exposure = 1.0f;
  bool json = false;
};

void runCompare(const CompareOptions& o) {
  const hp::LinearImage mask = o.mask.empty() ? hp::LinearImage() : hp::readPfm(o.mask);
  const hp::ImageComparison c = hp::compareImages(hp::readPfm(o.image), hp::readPfm(o.reference), mask, o.exposure);
  const nlohmann::json report = {{"psnr_db", c.psnrDb}, {"ssim", c.ssim}, {"luminance_ratio", c.luminanceRatio},
                                 {"red_blue_image", c.redBlueImage}, {"red_blue_reference", c.redBlueReference},
                                 {"pixels", c.pixels}};
  if (o.json) {
    std::cout << hp::jsonText(report) << "\n";
    return;
  }
  std::cout << "PSNR " << c.psnrDb << " dB, SSIM " << c.ssim << ", luminance ratio " << c.luminanceRatio
            << ", red/blue " << c.redBlueImage << " vs " << c.redBlueReference << " over " << c.pixels << " pixels\n";
}

void setupCompare(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "PSNR, SSIM and luminance ratio of an image against a reference (PFM)");
  cmd->add_option("--image", o->image, "Linear RGB image (.pfm), e.g. an export's realtime.pfm")->required();
  cmd->add_option("--reference", o->reference, "Linear RGB reference (.pfm), e.g. from hairpipe reference")->required();
  cmd->add_option("--mask", o->mask, "One-channel PFM: pixels > 0.5 are compared (default: all)");
  cmd->add_option("--exposure", o->exposure, "Exposure before the display curve (default 1)");
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o] { runCompare(*o); });
}
}  // namespace

HP_CLI_COMMAND(setupCompare);
}  // namespace hp::cli::cmd_compare
