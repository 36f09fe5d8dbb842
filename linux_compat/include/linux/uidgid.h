/*
 * linux/uidgid.h — the kernel's user and group IDs (Linux 6.1's
 * include/linux/uidgid.h and uapi/asm-generic/posix_types.h): wrapped in a
 * struct so that an ID of one namespace is never used as another's by
 * mistake.  There is one namespace here: the IDs are the values.
 */
#ifndef _LINUX_UIDGID_H
#define _LINUX_UIDGID_H

typedef unsigned int __kernel_uid32_t;
typedef unsigned int __kernel_gid32_t;

typedef struct {
	__kernel_uid32_t val;
} kuid_t;

typedef struct {
	__kernel_gid32_t val;
} kgid_t;

#define KUIDT_INIT(value)	((kuid_t){ value })
#define KGIDT_INIT(value)	((kgid_t){ value })
#define GLOBAL_ROOT_UID		KUIDT_INIT(0)
#define GLOBAL_ROOT_GID		KGIDT_INIT(0)

static inline __kernel_uid32_t __kuid_val(kuid_t uid)
{
	return uid.val;
}

static inline __kernel_gid32_t __kgid_val(kgid_t gid)
{
	return gid.val;
}

static inline int uid_eq(kuid_t left, kuid_t right)
{
	return __kuid_val(left) == __kuid_val(right);
}

static inline int gid_eq(kgid_t left, kgid_t right)
{
	return __kgid_val(left) == __kgid_val(right);
}

#endif /* _LINUX_UIDGID_H */
