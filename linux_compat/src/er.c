/*
 * er.c — Linux results as TOPPERS error codes (linux_compat/er.h).
 */
#include <linux/errno.h>
#include <linux_compat/er.h>

ER lx_errno_to_er(long ret)
{
	if (ret >= 0)
		return E_OK;
	switch (ret) {
	case -EINVAL:
		return E_PAR;
	case -EFAULT:
		return E_MACV;
	case -ENODEV:
	case -ENXIO:
	case -EBADF:
		return E_OBJ;
	case -EBUSY:
		return E_QOVR;
	case -EAGAIN:
	case -ETIME:
		return E_TMOUT;
	case -ERESTARTSYS:
	case -EINTR:
		return E_RLWAI;
	case -ENOMEM:
		return E_NOMEM;
	case -EOPNOTSUPP:
	case -ENOTTY:
		return E_NOSPT;
	default:
		return E_SYS;
	}
}
