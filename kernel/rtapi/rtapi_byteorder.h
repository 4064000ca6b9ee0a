/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_byteorder.h - byte order of the target (intro(3rtapi), "rtapi_byteorder.h"):
 * RTAPI_BIG_ENDIAN, RTAPI_LITTLE_ENDIAN and RTAPI_FLOAT_BIG_ENDIAN are 1 or 0. Taken
 * from the compiler's predefined macros, so kernel and userspace builds agree. */
#ifndef RTAPI_BYTEORDER_H
#define RTAPI_BYTEORDER_H

#if !defined(__BYTE_ORDER__) || !defined(__ORDER_BIG_ENDIAN__)
#error "rtapi_byteorder.h needs a compiler that predefines __BYTE_ORDER__ (gcc, clang)"
#endif

#if __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
#define RTAPI_BIG_ENDIAN 1
#define RTAPI_LITTLE_ENDIAN 0
#else
#define RTAPI_BIG_ENDIAN 0
#define RTAPI_LITTLE_ENDIAN 1
#endif

#if defined(__FLOAT_WORD_ORDER__) && __FLOAT_WORD_ORDER__ == __ORDER_BIG_ENDIAN__
#define RTAPI_FLOAT_BIG_ENDIAN 1
#else
#define RTAPI_FLOAT_BIG_ENDIAN 0
#endif

#endif /* RTAPI_BYTEORDER_H */
