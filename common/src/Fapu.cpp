#include <lacrima/Fapu.h>
