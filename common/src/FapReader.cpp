#include <lacrima/FapReader.h>
