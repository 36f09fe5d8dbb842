/* lms_codegen_hack.h — the lms_codegen conformance module's interface (C types only). */
#ifndef LMS_CODEGEN_HACK_H
#define LMS_CODEGEN_HACK_H

#define LMS_CODEGEN_API __attribute__((visibility("default")))

/* Runs the module's init (0 or -errno): eHRPWM1, eCAP0 and SPI0 set up. */
LMS_CODEGEN_API int lms_codegen_load(void);
LMS_CODEGEN_API void lms_codegen_unload(void);
/* One command of len bytes (d_sound's write()): len or -errno. */
LMS_CODEGEN_API int lms_codegen_command(const void *cmd, int len);
/* The frequency the last tone command chose (Hz). */
LMS_CODEGEN_API unsigned lms_codegen_frequency(void);

#endif
