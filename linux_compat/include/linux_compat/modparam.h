/*
 * linux_compat/modparam.h — module parameters from the RTOS side (the boot
 * configuration or a test sets them before module_init, as insmod's
 * arguments would), with TOPPERS results.  Kept out of linux/moduleparam.h:
 * a driver sees only Linux names.
 */
#ifndef _LINUX_COMPAT_MODPARAM_H
#define _LINUX_COMPAT_MODPARAM_H

#include <t_stddef.h>

/*
 * Sets parameter `param` of module `module` from text before the module is
 * initialised.  charp keeps the pointer (the text must stay valid: a string
 * literal or static storage).  Returns E_OK; E_PAR for NULL arguments or text
 * the type does not accept; E_NOEXS if no such module parameter is linked;
 * E_OBJ if the module has already been initialised.
 */
ER lx_module_param_set(const char *module, const char *param, const char *value);

/* Writes the value of a parameter as text into buf; returns E_OK, E_NOEXS or E_PAR. */
ER lx_module_param_get(const char *module, const char *param, char *buf, SIZE len);

#endif /* _LINUX_COMPAT_MODPARAM_H */
