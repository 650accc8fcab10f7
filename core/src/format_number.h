// Transitional: core's formatter is public now (rigid/format.h).
#pragma once
#include "rigid/format.h"
