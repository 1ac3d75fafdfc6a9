// datomsim's public API: everything a module program and its executable need, in one include.
// docs/writing-programs.md is the tutorial.
#pragma once

#include "datomsim/cell.h"
#include "datomsim/main.h"
#include "datomsim/message.h"
#include "datomsim/move_result.h"
#include "datomsim/parameters.h"
#include "datomsim/program.h"
#include "datomsim/random.h"
#include "datomsim/result.h"
#include "datomsim/time.h"
#include "datomsim/values.h"
