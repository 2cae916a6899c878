/* A stand-in library whose isoform_version() is not ISOFORM_VERSION: the
 * add-on's native module must refuse it before calling anything else. */
#include "isoform.h"

int isoform_version(void) { return ISOFORM_VERSION + 1; }
