/*
 * linux/bug.h — BUG, WARN and their conditional forms.
 *
 * BUG() reports the file and line and stops the system (host: a bug report
 * and abort; AM1808: a LOG_EMERG line, then the CPU is locked and halted).
 * WARN*() print "WARNING: file:line" plus the message and count as a bug
 * report (on the host the test run fails unless bugs are expected); they
 * return the condition, as in Linux.
 */
#ifndef _LINUX_BUG_H
#define _LINUX_BUG_H

#include <linux/compiler.h>
#include <linux/build_bug.h>
#include <linux_compat/report.h>

#define BUG()		lx_bug(__FILE__, __LINE__)
#define BUG_ON(cond)	do { if (unlikely(cond)) BUG(); } while (0)

#define WARN_ON(cond) ({						\
	int __lx_warn_ret = !!(cond);					\
	if (unlikely(__lx_warn_ret))					\
		lx_warn(__FILE__, __LINE__, "%s", "WARN_ON(" #cond ")");	\
	unlikely(__lx_warn_ret);					\
})

#define WARN(cond, fmt, ...) ({						\
	int __lx_warn_ret = !!(cond);					\
	if (unlikely(__lx_warn_ret))					\
		lx_warn(__FILE__, __LINE__, fmt, ##__VA_ARGS__);	\
	unlikely(__lx_warn_ret);					\
})

#define WARN_ON_ONCE(cond) ({						\
	static bool __lx_warned;					\
	int __lx_warn_ret = !!(cond);					\
	if (unlikely(__lx_warn_ret && !__lx_warned)) {			\
		__lx_warned = true;					\
		lx_warn(__FILE__, __LINE__, "%s", "WARN_ON_ONCE(" #cond ")"); \
	}								\
	unlikely(__lx_warn_ret);					\
})

#define WARN_ONCE(cond, fmt, ...) ({					\
	static bool __lx_warned;					\
	int __lx_warn_ret = !!(cond);					\
	if (unlikely(__lx_warn_ret && !__lx_warned)) {			\
		__lx_warned = true;					\
		lx_warn(__FILE__, __LINE__, fmt, ##__VA_ARGS__);	\
	}								\
	unlikely(__lx_warn_ret);					\
})

#endif /* _LINUX_BUG_H */
