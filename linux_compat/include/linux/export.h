/*
 * linux/export.h — EXPORT_SYMBOL: checks that the symbol is declared and
 * gives it default visibility.  A module built with a private namespace
 * (compiled -fvisibility=hidden, linked -r, hidden symbols localized) keeps
 * exactly its exported symbols and its hack's interface global, as insmod
 * resolves only exported symbols between modules.
 */
#ifndef _LINUX_EXPORT_H
#define _LINUX_EXPORT_H

#define EXPORT_SYMBOL(sym)		extern __typeof__(sym) sym __attribute__((visibility("default")))
#define EXPORT_SYMBOL_GPL(sym)		extern __typeof__(sym) sym __attribute__((visibility("default")))
#define EXPORT_SYMBOL_NS(sym, ns)	extern __typeof__(sym) sym __attribute__((visibility("default")))
#define EXPORT_SYMBOL_NS_GPL(sym, ns)	extern __typeof__(sym) sym __attribute__((visibility("default")))

#endif /* _LINUX_EXPORT_H */
