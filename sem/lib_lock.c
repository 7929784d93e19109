#include "lib_lock.h"

#include <pthread.h>

/* Process-wide on purpose: it stands for the libraries' own process-wide
 * state (lib_lock.h). */
static pthread_mutex_t lib_mutex = PTHREAD_MUTEX_INITIALIZER;

void sem_lib_lock(void)
{
    pthread_mutex_lock(&lib_mutex);
}

void sem_lib_unlock(void)
{
    pthread_mutex_unlock(&lib_mutex);
}
