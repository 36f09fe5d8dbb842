/* lms_names_hack.h — the lms_names conformance module's interface (C types only). */
#ifndef LMS_NAMES_HACK_H
#define LMS_NAMES_HACK_H

#define LMS_HACK_API __attribute__((visibility("default")))

/* Runs the module's init (0 or -errno) / exit. */
LMS_HACK_API int lms_names_load(void);
LMS_HACK_API void lms_names_unload(void);
/* Opens /dev/lms_names, writes `mode`, reads its 3-byte reply (state, result,
 * command count) and closes it; 0 or -errno. */
LMS_HACK_API int lms_names_command(unsigned char mode, unsigned char reply[3]);

#endif
