#!/usr/bin/env bash
# The files -o writes (docs/output-formats.md, "How files are written"): a
# regular file through a hidden temporary beside it and a rename; devices and
# FIFOs written in place and left as they are; a symbolic link kept, its target
# written; a link planted at FILE.tmp and a user's own FILE.tmp never touched;
# every failure a message naming the file and the reason, exit status 2, the
# old file intact; and no temporary left behind, after success or failure.
# Each case runs in a directory of its own whose listing is checked after.
# usage: test_safe_files.sh BUILD_DIR SOURCE_DIR
set -u
bin="$1/intercurve"
problem="$2/examples/viviani-implicit.json"
pass=0
fail=0
check() { # description, condition status
    if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $1"; fi
}
top=$(mktemp -d)
trap 'rm -rf "$top"' EXIT
umask 022

# The reference of each command: trace's through standard output (another
# path), plot's a fresh file checked to be a whole PNG (signature, IEND).
"$bin" trace "$problem" >"$top/ref.json"
check "trace to standard output" $?
"$bin" plot "$problem" -o "$top/ref.png"
check "plot to a new file" $?
[ "$(head -c 8 "$top/ref.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] &&
    [ "$(tail -c 8 "$top/ref.png" | head -c 4)" = IEND ]
check "plot: a whole PNG" $?

# A fresh directory for a case; prints its path.
fresh() {
    mkdir "$top/$1" && echo "$top/$1"
}
# Runs `intercurve CMD PROBLEM -o TARGET` with a time limit (a FIFO without a
# reader would wait); sets rc and err.
run() { # cmd target
    timeout 120 "$bin" "$1" "$problem" -o "$2" >"$top/stdout" 2>"$top/stderr"
    rc=$?
    err=$(cat "$top/stderr")
}
# The directory holds exactly these names: nothing stray, nothing lost.
only() { # description dir names...
    local what="$1" dir="$2"
    shift 2
    local want got
    want=$(printf '%s\n' "$@" | sort | tr '\n' ' ')
    got=$(find "$dir" -mindepth 1 -maxdepth 1 -printf '%f\n' | sort | tr '\n' ' ')
    [ "$got" = "$want" ]
    check "$what: the directory holds only '$want' (has '$got')" $?
}
# A failure: exit status 2 and a message with each part.
failed() { # description parts...
    local what="$1"
    shift
    [ "$rc" -eq 2 ]
    check "$what: exit status 2 (got $rc)" $?
    for part in "$@"; do
        case "$err" in *"$part"*) check "$what: message has '$part'" 0 ;;
        *) check "$what: message has '$part' (got '$err')" 1 ;;
        esac
    done
}
is_mode() { # description file mode
    local got
    got=$(stat -c %a "$2")
    [ "$got" = "$3" ]
    check "$1: mode $3 (got $got)" $?
}

all_dev_ok=1
for cmd in trace plot; do
    case $cmd in trace) ext=json ;; plot) ext=png ;; esac
    ref="$top/ref.$ext"

    # a new file: the content, the mode fopen would give (0666 less the umask)
    d=$(fresh "$cmd-new")
    run $cmd "$d/out.$ext"
    check "$cmd new file: exit 0 ($err)" $rc
    cmp -s "$d/out.$ext" "$ref"
    check "$cmd new file: content" $?
    is_mode "$cmd new file" "$d/out.$ext" 644
    only "$cmd new file" "$d" "out.$ext"
    d=$(fresh "$cmd-umask")
    (umask 027 && exec timeout 120 "$bin" $cmd "$problem" -o "$d/out.$ext")
    check "$cmd new file under umask 027: exit 0" $?
    is_mode "$cmd new file under umask 027" "$d/out.$ext" 640

    # an existing file: replaced, its permission bits kept
    d=$(fresh "$cmd-existing")
    echo old >"$d/out.$ext"
    chmod 600 "$d/out.$ext"
    run $cmd "$d/out.$ext"
    check "$cmd existing file: exit 0 ($err)" $rc
    cmp -s "$d/out.$ext" "$ref"
    check "$cmd existing file: replaced" $?
    is_mode "$cmd existing file" "$d/out.$ext" 600
    only "$cmd existing file" "$d" "out.$ext"

    # a FIFO: written in place (read by cat), still a FIFO
    d=$(fresh "$cmd-fifo")
    mkfifo "$d/out.$ext"
    timeout 120 cat "$d/out.$ext" >"$top/got" &
    reader=$!
    run $cmd "$d/out.$ext"
    # a writer that failed never opened the FIFO: the reader would wait on
    [ "$rc" -eq 0 ] || kill $reader 2>/dev/null
    wait $reader
    check "$cmd FIFO: exit 0 ($err)" $rc
    cmp -s "$top/got" "$ref"
    check "$cmd FIFO: the reader got the whole content" $?
    [ -p "$d/out.$ext" ]
    check "$cmd FIFO: still a FIFO" $?
    only "$cmd FIFO" "$d" "out.$ext"

    # a symbolic link into another directory: the link stays, its target is
    # replaced, the temporary was beside the target
    d=$(fresh "$cmd-link")
    mkdir "$d/sub"
    echo old >"$d/sub/real.$ext"
    ln -s "sub/real.$ext" "$d/link.$ext"
    run $cmd "$d/link.$ext"
    check "$cmd symlink: exit 0 ($err)" $rc
    [ -L "$d/link.$ext" ] && [ "$(readlink "$d/link.$ext")" = "sub/real.$ext" ]
    check "$cmd symlink: still the same link" $?
    cmp -s "$d/sub/real.$ext" "$ref"
    check "$cmd symlink: the target has the content" $?
    only "$cmd symlink" "$d" "link.$ext" sub
    only "$cmd symlink's target" "$d/sub" "real.$ext"

    # a dangling link: refused, nothing created through it
    d=$(fresh "$cmd-dangling")
    ln -s "missing.$ext" "$d/out.$ext"
    run $cmd "$d/out.$ext"
    failed "$cmd dangling symlink" "cannot write $d/out.$ext" "symbolic link"
    only "$cmd dangling symlink" "$d" "out.$ext"

    # links planted at the old temporary names (FILE.tmp, plot's FILE.tmp.EXT)
    # pointing to a victim: the victim is unchanged, the links stay
    d=$(fresh "$cmd-planted")
    echo victim >"$top/victim"
    ln -s "$top/victim" "$d/out.$ext.tmp"
    ln -s "$top/victim" "$d/out.$ext.tmp.$ext"
    run $cmd "$d/out.$ext"
    check "$cmd planted link: exit 0 ($err)" $rc
    [ "$(cat "$top/victim")" = victim ]
    check "$cmd planted link: the victim is unchanged" $?
    [ -L "$d/out.$ext.tmp" ] && [ -L "$d/out.$ext.tmp.$ext" ]
    check "$cmd planted link: the links stay" $?
    cmp -s "$d/out.$ext" "$ref"
    check "$cmd planted link: content" $?
    only "$cmd planted link" "$d" "out.$ext" "out.$ext.tmp" "out.$ext.tmp.$ext"

    # a user's own FILE.tmp: untouched after a success and after a failure
    d=$(fresh "$cmd-users-tmp")
    echo mine >"$d/out.$ext.tmp"
    run $cmd "$d/out.$ext"
    check "$cmd user's FILE.tmp: exit 0 ($err)" $rc
    [ "$(cat "$d/out.$ext.tmp")" = mine ]
    check "$cmd user's FILE.tmp: unchanged after a success" $?
    mkdir "$d/dir.$ext"
    echo mine >"$d/dir.$ext.tmp"
    run $cmd "$d/dir.$ext"
    [ "$rc" -ne 0 ] && [ "$(cat "$d/dir.$ext.tmp")" = mine ]
    check "$cmd user's FILE.tmp: unchanged after a failure" $?
    only "$cmd user's FILE.tmp" "$d" "out.$ext" "out.$ext.tmp" "dir.$ext" "dir.$ext.tmp"

    # failures that hold for root too: a directory that does not exist, a
    # path through a regular file, a target that is a directory
    d=$(fresh "$cmd-failures")
    run $cmd "$d/nodir/out.$ext"
    failed "$cmd into a missing directory" "cannot write $d/nodir/out.$ext" \
        "No such file or directory"
    echo data >"$d/file"
    run $cmd "$d/file/out.$ext"
    failed "$cmd through a regular file" "cannot write $d/file/out.$ext" "Not a directory"
    mkdir "$d/out.$ext"
    run $cmd "$d/out.$ext"
    failed "$cmd onto a directory" "cannot write $d/out.$ext" "Is a directory"
    [ -d "$d/out.$ext" ] && [ -z "$(ls -A "$d/out.$ext")" ]
    check "$cmd onto a directory: still an empty directory" $?
    only "$cmd failures" "$d" file "out.$ext"

    # a write that fails halfway (a file size limit: EFBIG): the old file is
    # intact and the temporary removed
    d=$(fresh "$cmd-too-large")
    echo old >"$d/out.$ext"
    (trap '' XFSZ && ulimit -f 8 && exec "$bin" $cmd "$problem" -o "$d/out.$ext") \
        >/dev/null 2>"$top/stderr"
    rc=$?
    err=$(cat "$top/stderr")
    failed "$cmd over the file size limit" "cannot write $d/out.$ext" "File too large"
    [ "$(cat "$d/out.$ext")" = old ]
    check "$cmd over the file size limit: the old file is intact" $?
    only "$cmd over the file size limit" "$d" "out.$ext"

    # device nodes of its own (root, on a file system that allows them): null
    # takes the output, full refuses it, directly and through a link; the
    # nodes stay devices. The machine's /dev is written below only when these
    # passed (or without root, who cannot replace it): a regression run as
    # root must not turn /dev/null into a regular file.
    d=$(fresh "$cmd-nodes")
    dev_ok=0
    [ "$(id -u)" -ne 0 ] && dev_ok=1
    if mknod "$d/null.$ext" c 1 3 2>/dev/null && mknod "$d/full.$ext" c 1 7 2>/dev/null; then
        before=$fail
        run $cmd "$d/null.$ext"
        check "$cmd device node null: exit 0 ($err)" $rc
        run $cmd "$d/full.$ext"
        failed "$cmd device node full" "cannot write $d/full.$ext: No space left on device"
        ln -s "full.$ext" "$d/link.$ext"
        run $cmd "$d/link.$ext"
        failed "$cmd link to a device node" "cannot write $d/link.$ext: No space left on device"
        [ -c "$d/null.$ext" ] && [ -c "$d/full.$ext" ] && [ -L "$d/link.$ext" ]
        check "$cmd device nodes: still character devices, the link a link" $?
        only "$cmd device nodes" "$d" "null.$ext" "full.$ext" "link.$ext"
        [ "$fail" -eq "$before" ] && dev_ok=1
    else
        echo "note: no device nodes in $top (mknod refused): those cases skipped"
    fi
    [ "$dev_ok" -eq 1 ] || all_dev_ok=0

    # The system calls, where strace runs: the temporary's name is random, so
    # only they show that it is hidden beside the target, created with O_EXCL
    # (which never follows a link planted at the name), synced and renamed over
    # the target, and that a device is opened without O_CREAT.
    if strace -o /dev/null true 2>/dev/null; then
        # LeakSanitizer cannot run under ptrace (make sanitize); the other
        # runs check for leaks
        no_lsan="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
        d=$(fresh "$cmd-syscalls")
        calls="$top/strace.$cmd"
        ASAN_OPTIONS=$no_lsan strace -f -e trace=open,openat,fsync,rename,renameat,renameat2 \
            -o "$calls" "$bin" $cmd "$problem" -o "$d/out.$ext" >/dev/null 2>&1
        check "$cmd under strace: exit 0" $?
        grep -F "\"$d/.out.$ext." "$calls" | grep -E "open.*\"$d/\.out\.$ext\.[A-Za-z0-9]{6}\"" |
            grep O_CREAT >"$top/created"
        [ "$(wc -l <"$top/created")" -eq 1 ] && grep -q O_EXCL "$top/created"
        check "$cmd syscalls: one hidden temporary beside the target, created with O_EXCL" $?
        grep -F "\"$d/.out.$ext." "$calls" | grep rename | grep -qF "\"$d/out.$ext\")"
        check "$cmd syscalls: the temporary renamed over the target" $?
        # synced first, or a crash could leave an empty file under the name
        sed -n '/^[0-9]* *fsync(/,$p' "$calls" | grep -q rename
        check "$cmd syscalls: the temporary synced before the rename" $?
        ! grep -F "\"$d/" "$calls" | grep O_CREAT | grep -qv O_EXCL
        check "$cmd syscalls: nothing in the directory created without O_EXCL" $?
        if [ "$dev_ok" -eq 1 ]; then
            ln -s /dev/null "$d/null.$ext"
            ASAN_OPTIONS=$no_lsan strace -f -e trace=open,openat -o "$calls" \
                "$bin" $cmd "$problem" -o "$d/null.$ext" >/dev/null 2>&1
            check "$cmd link to /dev/null under strace: exit 0" $?
            grep -F "\"$d/null.$ext\"" "$calls" | grep -q O_WRONLY &&
                ! grep -F "\"$d/null.$ext\"" "$calls" | grep -q O_CREAT
            check "$cmd syscalls: a link to a device opened in place, without O_CREAT" $?
            rm "$d/null.$ext"
        fi
        only "$cmd syscalls" "$d" "out.$ext"
    else
        echo "note: strace does not run here: the system calls not checked"
    fi

    # links to /dev/null and /dev/full (plot names its format by the extension)
    if [ "$dev_ok" -eq 1 ]; then
        d=$(fresh "$cmd-dev-links")
        ln -s /dev/null "$d/null.$ext"
        ln -s /dev/full "$d/full.$ext"
        run $cmd "$d/null.$ext"
        check "$cmd link to /dev/null: exit 0 ($err)" $rc
        run $cmd "$d/full.$ext"
        failed "$cmd link to /dev/full" "cannot write $d/full.$ext: No space left on device"
        [ -L "$d/null.$ext" ] && [ -L "$d/full.$ext" ]
        check "$cmd links to devices: still links" $?
        only "$cmd links to devices" "$d" "null.$ext" "full.$ext"
        [ -c /dev/null ] && [ -c /dev/full ]
        check "$cmd links to devices: /dev/null and /dev/full still character devices" $?
    fi
done

# /dev/null and /dev/full themselves (trace only: plot takes its format from
# the extension), when the device nodes above were written in place
if [ "$all_dev_ok" -eq 1 ]; then
    run trace /dev/null
    check "trace -o /dev/null: exit 0 ($err)" $rc
    run trace /dev/full
    failed "trace -o /dev/full" "cannot write /dev/full: No space left on device"
    [ -c /dev/null ] && [ -c /dev/full ]
    check "/dev/null and /dev/full: still character devices" $?
    [ -z "$(find /dev -maxdepth 1 \( -name '.null.*' -o -name '.full.*' \))" ]
    check "no temporary file in /dev" $?
else
    echo "note: the machine's /dev left alone: device nodes were not written in place"
fi
run plot /dev/full
[ "$rc" -eq 1 ] && [ -n "$err" ]
check "plot -o /dev/full: exit 1 with a message (no extension) ($err)" $?

echo "safe_files: $pass passed, $fail failed"
# a failure, or no check run at all, fails the test
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
