/* lms_gpio_hack.h — the lms_gpio conformance module's interface (C types only). */
#ifndef LMS_GPIO_HACK_H
#define LMS_GPIO_HACK_H

#define LMS_HACK_API __attribute__((visibility("default")))

/* Runs the module's init (0 or -errno) / exit. */
LMS_HACK_API int lms_gpio_load(void);
LMS_HACK_API void lms_gpio_unload(void);
/* Rising edges counted by its interrupt handler. */
LMS_HACK_API unsigned long lms_gpio_edges(void);
/* The board revision its init selected (its global Hw). */
LMS_HACK_API int lms_gpio_board(void);

#endif
