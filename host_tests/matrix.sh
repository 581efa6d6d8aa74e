#!/bin/bash
# SPDX-License-Identifier: MIT
# host_tests/matrix.sh: the build matrix over the compile-time options of
# lib/include/mdr_options.h (make matrix; MATRIX=short in make test).
#
# For each configuration: the library's sources compiled warning-free with
# the project's flags and the configuration's options, then test_config
# (host_tests/test_config.c: what is kept works, what is removed answers
# MDR_E_DISABLED) and every host suite built with the same options; a suite
# that needs something the configuration removes says so and is counted
# "not applicable" (host_tests/applies.h). Configurations the options
# forbid (q31 without the spring engine or without a float arithmetic)
# must stop the build with their #error.
#
#   MATRIX=short  the named configurations below: each option off at least
#                 once, the two minimal configurations of make size
#                 (port/configs/), the forbidden combinations (~70 s)
#   MATRIX=full   every combination of the 7 on/off options with three
#                 profile sets (all; paraboloid only; without the sphere
#                 and the wavy profile): 384 configurations, the library
#                 and test_config each (the suites run in the short set,
#                 where each applies to some configuration)
#
# Usage: host_tests/matrix.sh short|full <gen_tip.c>
set -u
mode=${1:-short}
gen_tip=${2:-build/host/gen_tip.c}
B=build/matrix
WARN="-Wall -Wextra -Wpedantic -Wconversion -Wdouble-promotion -Wshadow -Wvla -Werror"
LIBFLAGS="-std=c99 -ffreestanding -fno-math-errno -ffunction-sections -fdata-sections -O1 $WARN -Ilib/include -Iport/host"
TFLAGS="-std=c99 -D_GNU_SOURCE -Wall -Wextra -Werror -O1 -Ilib/include -Iref -Iport/host -Ihost_tests"
SUITES="test_config test_unit test_vectors test_engine test_q31 test_scene test_step test_critical test_fit"
[ "$mode" = full ] && SUITES=test_config

NOPROF="-DMDR_CFG_PROFILE_CONE=0 -DMDR_CFG_PROFILE_POWERLAW=0 -DMDR_CFG_PROFILE_FLATPUNCH=0 -DMDR_CFG_PROFILE_SPHERE=0 -DMDR_CFG_PROFILE_FLATTIP=0 -DMDR_CFG_PROFILE_WAVY=0 -DMDR_CFG_PROFILE_TABLE=0"
NOSPECIAL="-DMDR_CFG_PROFILE_SPHERE=0 -DMDR_CFG_PROFILE_WAVY=0"

configs() {
    if [ "$mode" = full ]; then
        local i b opts p
        for ((i = 0; i < 128; i++)); do
            for p in "" "$NOPROF" "$NOSPECIAL"; do
                opts=""
                b=0
                for o in F32 F64 Q31 ENGINE SCENE STRESS EVENTS; do
                    opts="$opts -DMDR_CFG_$o=$(((i >> b) & 1 ^ 1))"
                    b=$((b + 1))
                done
                echo "$opts $p"
            done
        done
    else
        echo "-DMDR_CFG_F64=0"
        echo "-DMDR_CFG_F32=0"
        echo "-DMDR_CFG_Q31=0"
        echo "-DMDR_CFG_Q31=0 -DMDR_CFG_ENGINE=0"
        echo "-DMDR_CFG_SCENE=0"
        echo "-DMDR_CFG_STRESS=0"
        echo "-DMDR_CFG_EVENTS=0"
        echo "-DMDR_CFG_Q31=0 -DMDR_CFG_ENGINE=0 -DMDR_CFG_SCENE=0 -DMDR_CFG_STRESS=0"
        echo "$NOSPECIAL -DMDR_CFG_STRESS=0"
        echo "-DMDR_CFG_PROFILE_PARABOLOID=0 -DMDR_CFG_F64=0"
        echo "-DMDR_USE_CONFIG -Iport/configs/minimal-scene"
        echo "-DMDR_USE_CONFIG -Iport/configs/minimal-q31"
        echo "-DMDR_CFG_ENGINE=0"
        echo "-DMDR_CFG_PROFILE_TABLE=0 -DMDR_CFG_F32=0"
        echo "-DMDR_CFG_F32=0 -DMDR_CFG_F64=0"
        echo "-DMDR_CFG_FIT=0"
        echo "-DMDR_CFG_FIT=0 -DMDR_CFG_F64=0 -DMDR_CFG_STRESS=0"
    fi
}

# one configuration: prints one result line; exit status 1 on a failure
run_one() {
    local n=$1 opts=$2 d=$B/$1 o t out na=0 ran=0
    rm -rf "$d" && mkdir -p "$d"
    for o in mdr_f32 mdr_f64 mdr_q31 mdr_status; do
        # shellcheck disable=SC2086
        if ! gcc $LIBFLAGS $opts -c lib/src/$o.c -o $d/$o.o 2> $d/build.log; then
            if grep -q '#error "MDR_CFG_Q31 needs' $d/build.log; then
                echo "[$n] $opts: refused by its #error, as it must be"
                return 0
            fi
            echo "[$n] $opts: library build FAILED"; cat $d/build.log; return 1
        fi
    done
    ar rcs $d/libmdr.a $d/mdr_f32.o $d/mdr_f64.o $d/mdr_q31.o $d/mdr_status.o
    for t in $SUITES; do
        local extra=""
        [ $t = test_engine ] && extra=$B/gen_tip.o
        # (test_q31 includes the q31 kernels of lib/src: mk/tests.mk test_cflags)
        [ $t = test_q31 ] && extra="-Ilib/src -fno-math-errno ref/mdr_ref.c -lgsl -lgslcblas"
        # shellcheck disable=SC2086
        if ! gcc $TFLAGS $opts host_tests/$t.c $extra $d/libmdr.a -lcmocka -lm -o $d/$t 2> $d/$t.build.log; then
            echo "[$n] $opts: $t build FAILED"; cat $d/$t.build.log; return 1
        fi
        # (test_fit: its round trips only, f64, f32 and every profile; its
        # sweeps run in make test's host suites, and no option but
        # MDR_CFG_FIT and those it needs, which make it not applicable,
        # changes the fit's code. The other suites without their long
        # sweeps, MDR_SKIP_TESTS (host_tests/applies.h): test_engine's
        # *_sampled (sampled profiles, 6.1 of its 7.6 s at -O1),
        # test_q31's scenes_vs_ref (the GSL reference's quadratures, 6.4
        # of 6.6 s), test_scene's scene_machine_sweep and test_step's
        # energy_long_run_f32 (1.9, 1.0 s), test_critical's sweeps over
        # sampled tips and the wavy profile's gripper scale (9.2 of its
        # 11.4 s at -O1, which ran in every configuration: 97 of the
        # matrix's 121 s): many points through the functions the suites'
        # other tests call in every configuration; make test's host,
        # sanitizer and mutation suites run them. MDR_SKIP_TESTS: comma-
        # separated patterns, host_tests/applies.h)
        local skip=""
        case $t in
        test_engine) skip='*_sampled' ;;
        test_q31) skip=scenes_vs_ref ;;
        test_scene) skip=scene_machine_sweep ;;
        test_step) skip=energy_long_run_f32 ;;
        test_critical) skip=table_quantized_heights_f32,table_measured_tips_f32,table_worn_tip_kendall,table_critical_vs_profiles,table_cone_no_false_kinks,wavy_gripper_scale ;;
        esac
        if ! out=$(if [ $t = test_fit ]; then MDR_FIT_TESTS='test_roundtrip_*' ./$d/$t; \
                   elif [ -n "$skip" ]; then MDR_SKIP_TESTS=$skip ./$d/$t; else ./$d/$t; fi 2>&1); then
            echo "[$n] $opts: $t FAILED"; echo "$out" | tail -30; return 1
        fi
        if echo "$out" | grep -q '^not applicable'; then na=$((na + 1)); else ran=$((ran + 1)); fi
    done
    echo "[$n] $opts: warning-free, $ran suites passed, $na not applicable"
    rm -rf "$d"
}
export -f run_one
export B LIBFLAGS TFLAGS SUITES gen_tip

mkdir -p $B
# the const table of test_engine, compiled once (its layout is the same in
# every configuration)
gcc $TFLAGS -c "$gen_tip" -o $B/gen_tip.o || exit 1
n=0
configs | while IFS= read -r c; do n=$((n + 1)); printf '%s\t%s\n' "$n" "$c"; done > $B/list
total=$(wc -l < $B/list)
if ! tr '\n' '\0' < $B/list | xargs -0 -P 2 -I{} bash -c 'IFS=$'"'"'\t'"'"' read -r n o <<< "{}"; run_one "$n" "$o"'; then
    echo "matrix ($mode): FAILED"
    exit 1
fi
echo "matrix ($mode): $total configurations, all warning-free and passing the suites that apply"
