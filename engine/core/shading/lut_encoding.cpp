#include "engine/core/shading/lut_encoding.h"

#include "engine/core/byte_stream.h"
#include "engine/core/error.h"

namespace hp {
namespace {
// A texture's shape fits its data, and no axis is absurd (a damaged stream cannot make a huge texture).
void checkTexture(const LutTexture& t) {
  const std::size_t expected = std::size_t(t.width) * t.height * t.channels;
  if (t.width > 65536 || t.height > 65536 || t.channels != 4 || t.data.size() != expected)
    throw Error("marschner tables: texture " + t.name + " does not hold its " + std::to_string(t.width) + " x " +
                std::to_string(t.height) + " texels");
}

void putTexture(ByteWriter& out, const LutTexture& t) {
  out.putString(t.name);
  out.put(t.width);
  out.put(t.height);
  out.put(t.channels);
  out.put(t.format);
  out.put(t.scale);
  for (const std::string& name : t.channelNames) out.putString(name);
  out.putString(t.uAxis);
  out.putString(t.vAxis);
  out.putVector(t.data);
}

LutTexture getTexture(ByteReader& in) {
  LutTexture t;
  t.name = in.getString();
  t.width = in.get<std::uint32_t>();
  t.height = in.get<std::uint32_t>();
  t.channels = in.get<std::uint32_t>();
  t.format = in.get<LutFormat>();
  if (t.format != LutFormat::RGBA8Unorm && t.format != LutFormat::RGBA16F && t.format != LutFormat::RGBA32F)
    throw Error("marschner tables: texture " + t.name + " has an unknown format");
  t.scale = in.get<std::array<float, 4>>();
  for (std::string& name : t.channelNames) name = in.getString();
  t.uAxis = in.getString();
  t.vAxis = in.getString();
  t.data = in.getVector<float>();
  checkTexture(t);
  return t;
}

// Every table of MultipleScatteringTables, in one order for both directions.
template <typename Tables, typename Visit>
void eachTable(Tables& t, Visit&& visit) {
  visit(t.forwardAlbedo);
  visit(t.backAlbedo);
  visit(t.meanR);
  visit(t.meanTT);
  visit(t.meanTRT);
  visit(t.backScatter);
  visit(t.backShift);
  visit(t.backWidth);
}
}  // namespace

std::vector<std::byte> encodeLut(const MarschnerLut& lut) {
  ByteWriter out;
  out.put(lut.mode);
  out.put(lut.material);
  out.putString(lut.parameterisation);
  out.put<std::uint64_t>(lut.textures.size());
  for (const LutTexture& t : lut.textures) putTexture(out, t);
  eachTable(lut.multipleScattering, [&](const auto& table) { out.putVector(table); });
  return out.take();
}

MarschnerLut decodeLut(std::span<const std::byte> bytes) {
  ByteReader in(bytes);
  MarschnerLut lut;
  lut.mode = in.get<LutMode>();
  if (lut.mode != LutMode::Direct && lut.mode != LutMode::Paper && lut.mode != LutMode::Float &&
      lut.mode != LutMode::Physical)
    throw Error("marschner tables: an unknown mode");
  lut.material = in.get<HairMaterial>();
  lut.parameterisation = in.getString();
  const auto textures = in.get<std::uint64_t>();
  if (textures > 8) throw Error("marschner tables: " + std::to_string(textures) + " textures");
  for (std::uint64_t i = 0; i < textures; ++i) lut.textures.push_back(getTexture(in));
  eachTable(lut.multipleScattering, [&](auto& table) {
    table = in.getVector<typename std::remove_reference_t<decltype(table)>::value_type>();
  });
  if (!in.atEnd()) throw Error("marschner tables: bytes left after the last table");
  return lut;
}
}  // namespace hp
