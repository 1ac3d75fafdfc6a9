// datomsim: the command line. Each subcommand parses its options and calls the layers in src/;
// errors reach the user as one line naming the file, line or value at fault, with status 1.
#include "datomsim/main.h"

int main(int argc, char** argv) {
  return datomsim::main(argc, argv);
}
