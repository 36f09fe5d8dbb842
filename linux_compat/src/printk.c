/*
 * printk.c — printk over the TOPPERS syslog, and the scnprintf family.
 */
#include <linux/kernel.h>
#include <linux/printk.h>
#include <t_syslog.h>

/* Syslog priority of a Linux log level digit; no level: LOG_WARNING (Linux's default). */
static uint_t syslog_priority_of(char level)
{
	if (level >= '0' && level <= '7')
		return (uint_t)(level - '0');   /* KERN_EMERG..KERN_DEBUG match LOG_EMERG..LOG_DEBUG */
	return LOG_WARNING;
}

/* Formats the message (level prefix stripped) and logs it; returns the characters logged. */
int vprintk(const char *fmt, va_list args)
{
	char line[LX_PRINTK_LINE_MAX];
	char level = 0;
	int len;

	if (fmt == NULL)
		return 0;
	while (fmt[0] == KERN_SOH_ASCII && fmt[1] != '\0') {
		if (fmt[1] != 'c')
			level = fmt[1];
		fmt += 2;
	}
	len = vscnprintf(line, sizeof(line), fmt, args);
	/* syslog adds its own line end; Linux messages usually carry one. */
	while (len > 0 && line[len - 1] == '\n')
		line[--len] = '\0';
	if (len == 0)
		return 0;
	syslog(syslog_priority_of(level), "%s", line);
	return len;
}

/* Logs one message at its KERN_* level; any context. */
int printk(const char *fmt, ...)
{
	va_list args;
	int len;

	va_start(args, fmt);
	len = vprintk(fmt, args);
	va_end(args);
	return len;
}

/* vsnprintf that returns what was stored (excluding the NUL), never more than size-1. */
int vscnprintf(char *buf, size_t size, const char *fmt, va_list args)
{
	int len;

	if (size == 0)
		return 0;
	len = vsnprintf(buf, size, fmt, args);
	if (len < 0) {
		buf[0] = '\0';
		return 0;
	}
	return (size_t)len < size ? len : (int)(size - 1);
}

/* snprintf that returns what was stored (excluding the NUL). */
int scnprintf(char *buf, size_t size, const char *fmt, ...)
{
	va_list args;
	int len;

	va_start(args, fmt);
	len = vscnprintf(buf, size, fmt, args);
	va_end(args);
	return len;
}
