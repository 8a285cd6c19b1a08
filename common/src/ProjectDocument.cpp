#include <lacrima/ProjectDocument.h>
