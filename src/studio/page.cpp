#include "studio/page.h"

namespace datomsim::studio {

std::string studioPage(const std::string& viewerBundle) {
  // The element datomsim-studio puts the bundle in its studio mode (viewer/src/studio.js).
  return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>datomsim studio</title>\n</head>\n<body>\n<div id=\"datomsim-studio\"></div>\n"
         "<script>\n" +
         viewerBundle + "\n</script>\n</body>\n</html>\n";
}

}  // namespace datomsim::studio
