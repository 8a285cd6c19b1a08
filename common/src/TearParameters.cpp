#include <lacrima/TearParameters.h>
