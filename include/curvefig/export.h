/*
** CF_API marks the functions a curvefig library exports.  The libraries are
** built with hidden visibility, so that what is not marked (the cf__
** internals shared between the files of one library) stays inside it.
*/
#ifndef CURVEFIG_EXPORT_H
#define CURVEFIG_EXPORT_H

#if defined(_WIN32) || defined(__CYGWIN__)
#  if defined(CF_BUILDING_LIBRARY)
#    define CF_API __declspec(dllexport)
#  else
#    define CF_API
#  endif
#elif defined(__GNUC__) && __GNUC__ >= 4
#  define CF_API __attribute__((visibility("default")))
#else
#  define CF_API
#endif

#endif
