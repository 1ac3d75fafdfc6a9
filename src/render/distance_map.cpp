// The distance map as files: draws the laid-out picture on a cairo image (PNG) or SVG surface,
// makes the SVG's bytes independent of what else the process drew, and writes files atomically.
#include "render/distance_map.h"
#include "render/cairo_stream.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <string_view>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "render/distance_map_drawing.h"
#include "render/distance_map_layout.h"
#include "render/picture_size.h"
#include "render/svg_ids.h"

namespace datomsim::render {

namespace {

using detail::Scene;

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct ContextDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

Error cairoError(std::string_view what, cairo_status_t status) {
  return Error{fmt::format("{}: {}", what, cairo_status_to_string(status))};
}

// Draws on the surface and reports cairo's first error, if any.
Status drawOn(cairo_surface_t* surface, const Scene& scene, const DistanceMapPicture& picture,
              const DistanceMapLayout& layout, detail::CellPainter& painter) {
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    return cairoError("cannot create the picture", cairo_surface_status(surface));
  }
  const ContextPtr cr(cairo_create(surface));
  detail::draw(cr.get(), scene, picture, layout, painter);
  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
    return cairoError("cannot draw the picture", cairo_status(cr.get()));
  }
  return Ok{};
}

// Text for an SVG element's content.
std::string escapeXml(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// The picture's text lines as the SVG's title and description, for readers that do not see the
// drawing (its text is glyph outlines, not characters): right after the opening <svg> tag.
void addTitle(std::string& svg, const DistanceMapPicture& picture, const Scene& scene,
              const DistanceMapLayout& layout) {
  const size_t open = svg.find("<svg");
  const size_t end = open == std::string::npos ? open : svg.find('>', open);
  if (end == std::string::npos) return;
  std::string description = scene.summary;
  if (!layout.note.empty()) description += ". " + layout.note;
  svg.insert(end + 1, fmt::format("\n<title>{}</title>\n<desc>{}</desc>", escapeXml(picture.title),
                                  escapeXml(description)));
}

Status writeWith(Result<std::string> (*render)(const DistanceMapPicture&),
                 const DistanceMapPicture& picture, const std::filesystem::path& path) {
  Result<std::string> bytes = render(picture);
  if (!bytes) return Error{fmt::format("cannot write {}: {}", path.string(), bytes.error())};
  return writeFileAtomically(path, *bytes);
}

}  // namespace

Result<std::string> renderDistanceMapPng(const DistanceMapPicture& picture) {
  const Result<Scene> scene = detail::prepare(picture);
  if (!scene) return Error{scene.error()};
  const DistanceMapLayout layout = detail::layoutOf(*scene, picture);
  if (Status fits = checkPictureSide(layout.width, layout.height); !fits)
    return Error{fits.error()};
  // RGB without alpha: the background is opaque white, and the files are smaller.
  const SurfacePtr surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, layout.width, layout.height));
  detail::CairoCellPainter painter;
  if (Status drawn = drawOn(surface.get(), *scene, picture, layout, painter); !drawn)
    return Error{drawn.error()};
  std::string bytes;
  const cairo_status_t status =
      cairo_surface_write_to_png_stream(surface.get(), detail::appendToString, &bytes);
  if (status != CAIRO_STATUS_SUCCESS) return cairoError("cannot encode the PNG", status);
  return bytes;
}

Result<std::string> renderDistanceMapSvg(const DistanceMapPicture& picture) {
  const Result<Scene> scene = detail::prepare(picture);
  if (!scene) return Error{scene.error()};
  const DistanceMapLayout layout = detail::layoutOf(*scene, picture);
  if (Status fits = checkPictureSide(layout.width, layout.height); !fits)
    return Error{fits.error()};
  std::string bytes;
  detail::SvgCellPainter painter;
  {
    const SurfacePtr surface(cairo_svg_surface_create_for_stream(detail::appendToString, &bytes,
                                                                 layout.width, layout.height));
    // Pixels, not points, so that the SVG and the PNG have the same size on screen.
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
    if (Status drawn = drawOn(surface.get(), *scene, picture, layout, painter); !drawn) {
      return Error{drawn.error()};
    }
    // Finishing writes the document's end; only then are the bytes complete.
    cairo_surface_finish(surface.get());
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
      return cairoError("cannot encode the SVG", cairo_surface_status(surface.get()));
    }
  }
  if (Status placed = painter.replacePlaceholders(bytes); !placed) return Error{placed.error()};
  renumberSurfaceIds(bytes);
  addTitle(bytes, picture, *scene, layout);
  return bytes;
}

Result<std::string> renderSideBySidePng(const std::vector<DistanceMapPicture>& pictures) {
  struct Laid {
    Scene scene;
    DistanceMapLayout layout;
  };
  std::vector<Laid> laid;
  int width = 0, height = 0;
  constexpr int kGap = 24;
  for (size_t i = 0; i < pictures.size(); ++i) {
    Result<Scene> scene = detail::prepare(pictures[i]);
    if (!scene) return Error{fmt::format("picture {}: {}", i + 1, scene.error())};
    const DistanceMapLayout layout = detail::layoutOf(*scene, pictures[i]);
    width += layout.width + (i ? kGap : 0);
    height = std::max(height, layout.height);
    laid.push_back({std::move(scene).value(), layout});
  }
  if (Status fits = checkPictureSide(width, height); !fits) {
    return Error{"side by side, " + fits.error()};
  }
  const SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    return cairoError("cannot create the picture", cairo_surface_status(surface.get()));
  }
  {
    const ContextPtr cr(cairo_create(surface.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    double left = 0;
    for (size_t i = 0; i < laid.size(); ++i) {
      cairo_save(cr.get());
      cairo_translate(cr.get(), left, 0);
      cairo_rectangle(cr.get(), 0, 0, laid[i].layout.width, laid[i].layout.height);
      cairo_clip(cr.get());
      detail::CairoCellPainter painter;
      detail::draw(cr.get(), laid[i].scene, pictures[i], laid[i].layout, painter);
      cairo_restore(cr.get());
      left += laid[i].layout.width + kGap;
    }
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
      return cairoError("cannot draw the pictures", cairo_status(cr.get()));
    }
  }
  std::string bytes;
  const cairo_status_t status =
      cairo_surface_write_to_png_stream(surface.get(), detail::appendToString, &bytes);
  if (status != CAIRO_STATUS_SUCCESS) return cairoError("cannot encode the PNG", status);
  return bytes;
}

Status writeSideBySidePng(const std::vector<DistanceMapPicture>& pictures,
                          const std::filesystem::path& path) {
  Result<std::string> bytes = renderSideBySidePng(pictures);
  if (!bytes) return Error{fmt::format("cannot write {}: {}", path.string(), bytes.error())};
  return writeFileAtomically(path, *bytes);
}

Status writeDistanceMapPng(const DistanceMapPicture& picture, const std::filesystem::path& path) {
  return writeWith(renderDistanceMapPng, picture, path);
}

Status writeDistanceMapSvg(const DistanceMapPicture& picture, const std::filesystem::path& path) {
  return writeWith(renderDistanceMapSvg, picture, path);
}

}  // namespace datomsim::render
