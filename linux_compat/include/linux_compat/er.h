/*
 * linux_compat/er.h — Linux results as TOPPERS error codes, for the hacks'
 * extended service calls (one mapping for every driver).
 */
#ifndef _LINUX_COMPAT_ER_H
#define _LINUX_COMPAT_ER_H

#include <t_stddef.h>

/*
 * A file operation's result as an ER: E_OK for ret >= 0; -EINVAL E_PAR,
 * -EFAULT E_MACV, -ENODEV/-ENXIO/-EBADF E_OBJ (no such device, or it went
 * away), -EBUSY E_QOVR, -EAGAIN/-ETIME E_TMOUT, -ERESTARTSYS/-EINTR E_RLWAI,
 * -ENOMEM E_NOMEM, -EOPNOTSUPP/-ENOTTY E_NOSPT, anything else E_SYS.
 */
ER lx_errno_to_er(long ret);

#endif /* _LINUX_COMPAT_ER_H */
