/*
 * linux/err.h — error values carried in pointers: the top MAX_ERRNO
 * addresses stand for -1..-MAX_ERRNO, as in Linux (never valid memory).
 */
#ifndef _LINUX_ERR_H
#define _LINUX_ERR_H

#include <linux/compiler.h>
#include <linux/types.h>
#include <linux/errno.h>

#define MAX_ERRNO	4095

#define IS_ERR_VALUE(x)	unlikely((unsigned long)(void *)(x) >= (unsigned long)-MAX_ERRNO)

/* The pointer standing for error (a negative errno). */
static inline void *__must_check ERR_PTR(long error)
{
	return (void *)error;
}

/* The negative errno ptr stands for (meaningful only if IS_ERR(ptr)). */
static inline long __must_check PTR_ERR(__force const void *ptr)
{
	return (long)ptr;
}

/* True if ptr stands for an error. */
static inline bool __must_check IS_ERR(__force const void *ptr)
{
	return IS_ERR_VALUE((unsigned long)ptr);
}

/* True if ptr is NULL or stands for an error. */
static inline bool __must_check IS_ERR_OR_NULL(__force const void *ptr)
{
	return unlikely(!ptr) || IS_ERR_VALUE((unsigned long)ptr);
}

/* ptr with its type cast away (to pass an error pointer on). */
static inline void *__must_check ERR_CAST(__force const void *ptr)
{
	return (void *)ptr;
}

/* PTR_ERR if ptr is an error, else 0. */
static inline int __must_check PTR_ERR_OR_ZERO(__force const void *ptr)
{
	return IS_ERR(ptr) ? (int)PTR_ERR(ptr) : 0;
}

#endif /* _LINUX_ERR_H */
