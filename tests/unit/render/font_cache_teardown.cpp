// Frees cairo's and fontconfig's process-wide caches after the last test.
//
// Text drawing fills caches that live until exit; LeakSanitizer (DATOMSIM_SANITIZE) reports them
// as leaks of this test executable. They are not leaks of the render layer, which keeps no state.
#include <cairo.h>
#include <fontconfig/fontconfig.h>
#include <gtest/gtest.h>

namespace datomsim::render {
namespace {

class FontCacheTeardown : public ::testing::Environment {
 public:
  void TearDown() override {
    // Cairo first: its font map holds fontconfig objects.
    cairo_debug_reset_static_data();
    FcFini();
  }
};

const ::testing::Environment* const kFontCacheTeardown =
    ::testing::AddGlobalTestEnvironment(new FontCacheTeardown);

}  // namespace
}  // namespace datomsim::render
