/// The Lagrange top: a heavy symmetric top about a fixed point on its axis.
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5*(a1*(omega.x*omega.x+omega.y*omega.y)+c*omega.z*omega.z),
    potential = mgl*gamma.z,
)]
pub struct LagrangeTop {
    /// Equatorial moment of inertia A₁ about the fixed point.
    pub a1: f64,
    /// Axial moment of inertia C.
    pub c: f64,
    /// m g l: weight times the distance of the centre of mass from the fixed point.
    pub mgl: f64,
}
#[doc(hidden)]
#[allow(
    non_upper_case_globals,
    unused_qualifications,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]
const _: () = {
    type __F64 = ::routh::__private::f64;
    type __Vector3 = ::routh::__private::Vector3<::routh::__private::f64>;
    type __Matrix3 = ::routh::__private::Matrix3<::routh::__private::f64>;
    type __RouthBundle = ::routh::__private::RouthBundle;
    type __GyroscopicSystem = ::routh::__private::GyroscopicSystem;
    type __FullEquations = ::routh::__private::FullEquations;
    type __FullJacobian = ::routh::__private::FullJacobian;
    type __ReducedEquations = ::routh::__private::ReducedEquations;
    type __Op = ::routh::__private::Op;
    type __Output = ::routh::__private::Output;
    type __Tape = ::routh::__private::Tape;
    type __CertificationTape = ::routh::__private::CertificationTape;
    type __RouthianTape = ::routh::__private::RouthianTape;
    type __MaybeTape = ::routh::__private::MaybeTape;
    type __MaybeRouthianTape = ::routh::__private::MaybeRouthianTape;
    type __FlowTape = ::routh::__private::FlowTape;
    type __MaybeFlowTape = ::routh::__private::MaybeFlowTape;
    type __MaybeRankOne = ::routh::__private::MaybeRankOne;
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for LagrangeTop {
        #[inline]
        fn lagrangian(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t11 = __v0 * __v0;
            let __t12 = __v1 * __v1;
            let __t15 = __v8 * __v2;
            let __t19 = __v9 * __v5;
            let __t13 = __t12 + __t11;
            let __t16 = __t15 * __v2;
            let __t14 = __t13 * __v7;
            let __t17 = __t14 + __t16;
            let __t18 = __t17 * 0.5f64;
            let __t22 = __t18 - __t19;
            __t22
        }
        #[inline]
        fn dl_domega(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t15 = __v8 * __v2;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            __Vector3::new(__t26, __t29, __t15)
        }
        #[inline]
        fn dl_dgamma(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v9: __F64 = self.mgl;
            let __t32 = -__v9;
            __Vector3::new(0f64, 0f64, __t32)
        }
        #[inline]
        fn d2l_domega2(&self, __gamma: &__Vector3) -> __Matrix3 {
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            __Matrix3::new(__v7, 0f64, 0f64, 0f64, __v7, 0f64, 0f64, 0f64, __v8)
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __Matrix3 {
            __Matrix3::new(0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64)
        }
        #[inline]
        fn energy(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t11 = __v0 * __v0;
            let __t12 = __v1 * __v1;
            let __t15 = __v8 * __v2;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t19 = __v9 * __v5;
            let __t13 = __t12 + __t11;
            let __t16 = __t15 * __v2;
            let __t33 = __t26 * __v0;
            let __t34 = __t29 * __v1;
            let __t14 = __t13 * __v7;
            let __t35 = __t34 + __t33;
            let __t17 = __t14 + __t16;
            let __t36 = __t35 + __t16;
            let __t18 = __t17 * 0.5f64;
            let __t22 = __t18 - __t19;
            let __t38 = __t36 - __t22;
            __t38
        }
        #[inline]
        fn cyclic_momentum(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __F64 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t42 = __t40 + __t39;
            let __t43 = __t42 + __t41;
            __t43
        }
        #[inline]
        fn full_equations(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __FullEquations {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t15 = __v8 * __v2;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t685 = __v9 * __v4;
            let __t687 = __v9 * __v3;
            let __t674 = __t15 * __v1;
            let __t677 = __t15 * __v0;
            let __t673 = __t29 * __v2;
            let __t678 = __t26 * __v2;
            let __t681 = __t26 * __v1;
            let __t682 = __t29 * __v0;
            let __t676 = __t673 - __t674;
            let __t680 = __t677 - __t678;
            let __t684 = __t681 - __t682;
            let __t689 = __t676 + __t685;
            let __t690 = __t680 - __t687;
            __FullEquations {
                inertia: __Matrix3::new(
                    __v7,
                    0f64,
                    0f64,
                    0f64,
                    __v7,
                    0f64,
                    0f64,
                    0f64,
                    __v8,
                ),
                right_side: __Vector3::new(__t689, __t690, __t684),
                rank_one: __MaybeRankOne::None,
            }
        }
        #[inline]
        fn full_jacobian(
            &self,
            __omega: &__Vector3,
            __gamma: &__Vector3,
        ) -> __FullJacobian {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t15 = __v8 * __v2;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t685 = __v9 * __v4;
            let __t687 = __v9 * __v3;
            let __t747 = __v7 * __v2;
            let __t749 = __v8 * __v1;
            let __t755 = __v8 * __v0;
            let __t674 = __t15 * __v1;
            let __t677 = __t15 * __v0;
            let __t673 = __t29 * __v2;
            let __t678 = __t26 * __v2;
            let __t681 = __t26 * __v1;
            let __t682 = __t29 * __v0;
            let __t748 = __t747 - __t15;
            let __t751 = __t29 - __t749;
            let __t753 = __t15 - __t747;
            let __t756 = __t755 - __t26;
            let __t676 = __t673 - __t674;
            let __t680 = __t677 - __t678;
            let __t32 = -__v9;
            let __t684 = __t681 - __t682;
            let __t689 = __t676 + __t685;
            let __t690 = __t680 - __t687;
            __FullJacobian {
                inertia: __Matrix3::new(
                    __v7,
                    0f64,
                    0f64,
                    0f64,
                    __v7,
                    0f64,
                    0f64,
                    0f64,
                    __v8,
                ),
                right_side: __Vector3::new(__t689, __t690, __t684),
                dright_domega: __Matrix3::new(
                    0f64,
                    __t748,
                    __t751,
                    __t753,
                    0f64,
                    __t756,
                    0f64,
                    0f64,
                    0f64,
                ),
                dright_dgamma: __Matrix3::new(
                    0f64,
                    __v9,
                    0f64,
                    __t32,
                    0f64,
                    0f64,
                    0f64,
                    0f64,
                    0f64,
                ),
                dinertia_dgamma: [
                    __Matrix3::new(0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64),
                    __Matrix3::new(0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64),
                    __Matrix3::new(0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64),
                ],
            }
        }
        #[inline]
        fn flow_tape(&self) -> __MaybeFlowTape {
            static __FLOW_OPS: [__Op; 23] = [
                __Op::Omega(0),
                __Op::Omega(1),
                __Op::Omega(2),
                __Op::Gamma(2),
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Const(0x3fe0000000000000),
                __Op::Powi(0, 2),
                __Op::Powi(1, 2),
                __Op::Add(8, 9),
                __Op::Mul(4, 10),
                __Op::Mul(2, 5),
                __Op::Mul(2, 12),
                __Op::Add(11, 13),
                __Op::Mul(7, 14),
                __Op::Mul(3, 6),
                __Op::Const(0x0),
                __Op::Neg(16),
                __Op::Add(15, 18),
                __Op::Mul(0, 4),
                __Op::Mul(1, 4),
                __Op::Neg(6),
            ];
            static __FLOW_OUT: [__Output; 22] = [
                __Output {
                    name: "lagrangian",
                    slot: 19,
                },
                __Output {
                    name: "dl_domega[0]",
                    slot: 20,
                },
                __Output {
                    name: "dl_domega[1]",
                    slot: 21,
                },
                __Output {
                    name: "dl_domega[2]",
                    slot: 12,
                },
                __Output {
                    name: "dl_dgamma[0]",
                    slot: 17,
                },
                __Output {
                    name: "dl_dgamma[1]",
                    slot: 17,
                },
                __Output {
                    name: "dl_dgamma[2]",
                    slot: 22,
                },
                __Output {
                    name: "d2l_domega2[0][0]",
                    slot: 4,
                },
                __Output {
                    name: "d2l_domega2[0][1]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega2[0][2]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega2[1][1]",
                    slot: 4,
                },
                __Output {
                    name: "d2l_domega2[1][2]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega2[2][2]",
                    slot: 5,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][0]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][1]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[0][2]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][0]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][1]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[1][2]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][0]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][1]",
                    slot: 17,
                },
                __Output {
                    name: "d2l_domega_dgamma[2][2]",
                    slot: 17,
                },
            ];
            static __FLOW: __Tape = __Tape::from_static(&__FLOW_OPS, &__FLOW_OUT, 3);
            __FlowTape::new(
                    __Tape::clone(&__FLOW),
                    <[__F64]>::to_vec(&[self.a1, self.c, self.mgl]),
                )
                .ok()
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for LagrangeTop {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t42 = __t40 + __t39;
            let __t47 = __t46 * __v7;
            let __t43 = __t42 + __t41;
            let __t50 = __t47 + __t49;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 / __t50;
            __t55
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t19 = __v9 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t33 = __t26 * __v0;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t34 = __t29 * __v1;
            let __t16 = __t15 * __v2;
            let __t42 = __t40 + __t39;
            let __t47 = __t46 * __v7;
            let __t35 = __t34 + __t33;
            let __t43 = __t42 + __t41;
            let __t50 = __t47 + __t49;
            let __t36 = __t35 + __t16;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 / __t50;
            let __t57 = __t55 * __t53;
            let __t63 = __t36 - __t57;
            let __t64 = __t63 * 0.5f64;
            let __t65 = __t64 - __t19;
            __t65
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t42 = __t40 + __t39;
            let __t47 = __t46 * __v7;
            let __t43 = __t42 + __t41;
            let __t50 = __t47 + __t49;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 / __t50;
            let __t73 = __t55 * __t66;
            let __t74 = __t55 * __t67;
            let __t75 = __t55 * __t48;
            let __t76 = __t73 + __t26;
            let __t77 = __t74 + __t29;
            let __t78 = __t75 + __t15;
            __Vector3::new(__t76, __t77, __t78)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Vector3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t42 = __t40 + __t39;
            let __t47 = __t46 * __v7;
            let __t43 = __t42 + __t41;
            let __t50 = __t47 + __t49;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 / __t50;
            let __t75 = __t55 * __t48;
            let __t73 = __t55 * __t66;
            let __t74 = __t55 * __t67;
            let __t78 = __t75 + __t15;
            let __t76 = __t73 + __t26;
            let __t77 = __t74 + __t29;
            let __t81 = __t78 * __t55;
            let __t79 = __t76 * __t55;
            let __t80 = __t77 * __t55;
            let __t82 = __t81 - __v9;
            __Vector3::new(__t79, __t80, __t82)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __F64 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t42 = __t40 + __t39;
            let __t47 = __t46 * __v7;
            let __t43 = __t42 + __t41;
            let __t50 = __t47 + __t49;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 / __t50;
            let __t150 = -__t55;
            __t150
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t47 = __t46 * __v7;
            let __t50 = __t47 + __t49;
            let __t54 = 1.0f64 / __t50;
            let __t89 = __t54 * __t66;
            let __t90 = __t54 * __t67;
            let __t91 = __t54 * __t48;
            let __t95 = __t89 * __t66;
            let __t110 = __t90 * __t67;
            let __t122 = __t91 * __t48;
            let __t98 = __t89 * __t67;
            let __t100 = __t89 * __t48;
            let __t113 = __t90 * __t48;
            let __t97 = __v7 - __t95;
            let __t112 = __v7 - __t110;
            let __t124 = __v8 - __t122;
            let __t99 = -__t98;
            let __t101 = -__t100;
            let __t114 = -__t113;
            __Matrix3::new(
                __t97,
                __t99,
                __t101,
                __t99,
                __t112,
                __t114,
                __t101,
                __t114,
                __t124,
            )
        }
        #[inline]
        fn d2r_domega_dgamma(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t69 = __t66 * 2f64;
            let __t71 = __t67 * 2f64;
            let __t72 = __t48 * 2f64;
            let __t47 = __t46 * __v7;
            let __t42 = __t40 + __t39;
            let __t50 = __t47 + __t49;
            let __t43 = __t42 + __t41;
            let __t54 = 1.0f64 / __t50;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 * __t54;
            let __t89 = __t54 * __t66;
            let __t90 = __t54 * __t67;
            let __t91 = __t54 * __t48;
            let __t83 = __t55 * __t69;
            let __t85 = __t55 * __t71;
            let __t87 = __t55 * __t72;
            let __t102 = __t55 * __v7;
            let __t129 = __t55 * __v8;
            let __t84 = __t83 + __t26;
            let __t86 = __t85 + __t29;
            let __t88 = __t87 + __t15;
            let __t103 = __t84 * __t89;
            let __t117 = __t86 * __t90;
            let __t130 = __t88 * __t91;
            let __t106 = __t86 * __t89;
            let __t108 = __t88 * __t89;
            let __t115 = __t84 * __t90;
            let __t120 = __t88 * __t90;
            let __t125 = __t84 * __t91;
            let __t127 = __t86 * __t91;
            let __t105 = __t102 - __t103;
            let __t119 = __t102 - __t117;
            let __t132 = __t129 - __t130;
            let __t107 = -__t106;
            let __t109 = -__t108;
            let __t116 = -__t115;
            let __t121 = -__t120;
            let __t126 = -__t125;
            let __t128 = -__t127;
            __Matrix3::new(
                __t105,
                __t107,
                __t109,
                __t116,
                __t119,
                __t121,
                __t126,
                __t128,
                __t132,
            )
        }
        #[inline]
        fn d2r_dgamma2(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __Matrix3 {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t69 = __t66 * 2f64;
            let __t71 = __t67 * 2f64;
            let __t72 = __t48 * 2f64;
            let __t47 = __t46 * __v7;
            let __t42 = __t40 + __t39;
            let __t50 = __t47 + __t49;
            let __t43 = __t42 + __t41;
            let __t54 = 1.0f64 / __t50;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 * __t54;
            let __t83 = __t55 * __t69;
            let __t85 = __t55 * __t71;
            let __t87 = __t55 * __t72;
            let __t102 = __t55 * __v7;
            let __t129 = __t55 * __v8;
            let __t84 = __t83 + __t26;
            let __t86 = __t85 + __t29;
            let __t88 = __t87 + __t15;
            let __t133 = __t102 * __t55;
            let __t146 = __t129 * __t55;
            let __t92 = __t84 * __t54;
            let __t93 = __t86 * __t54;
            let __t94 = __t88 * __t54;
            let __t134 = __t92 * __t84;
            let __t141 = __t93 * __t86;
            let __t147 = __t94 * __t88;
            let __t137 = __t92 * __t86;
            let __t139 = __t92 * __t88;
            let __t144 = __t93 * __t88;
            let __t136 = __t133 - __t134;
            let __t143 = __t133 - __t141;
            let __t149 = __t146 - __t147;
            let __t138 = -__t137;
            let __t140 = -__t139;
            let __t145 = -__t144;
            __Matrix3::new(
                __t136,
                __t138,
                __t140,
                __t138,
                __t143,
                __t145,
                __t140,
                __t145,
                __t149,
            )
        }
        #[inline]
        fn amended_potential(&self, __gamma: &__Vector3, __p_psi: __F64) -> __F64 {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t19 = __v9 * __v5;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t47 = __t46 * __v7;
            let __t50 = __t47 + __t49;
            let __t151 = __v6 / __t50;
            let __t153 = __t151 * __v6;
            let __t155 = __t153 * (-0.5f64);
            let __t156 = __t155 - __t19;
            let __t238 = -__t156;
            __t238
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __RouthBundle {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t19 = __v9 * __v5;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t33 = __t26 * __v0;
            let __t34 = __t29 * __v1;
            let __t69 = __t66 * 2f64;
            let __t47 = __t46 * __v7;
            let __t71 = __t67 * 2f64;
            let __t72 = __t48 * 2f64;
            let __t42 = __t40 + __t39;
            let __t16 = __t15 * __v2;
            let __t35 = __t34 + __t33;
            let __t50 = __t47 + __t49;
            let __t43 = __t42 + __t41;
            let __t36 = __t35 + __t16;
            let __t54 = 1.0f64 / __t50;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 * __t54;
            let __t89 = __t54 * __t66;
            let __t90 = __t54 * __t67;
            let __t91 = __t54 * __t48;
            let __t83 = __t55 * __t69;
            let __t85 = __t55 * __t71;
            let __t87 = __t55 * __t72;
            let __t57 = __t55 * __t53;
            let __t75 = __t55 * __t48;
            let __t73 = __t55 * __t66;
            let __t74 = __t55 * __t67;
            let __t102 = __t55 * __v7;
            let __t84 = __t83 + __t26;
            let __t86 = __t85 + __t29;
            let __t88 = __t87 + __t15;
            let __t63 = __t36 - __t57;
            let __t78 = __t75 + __t15;
            let __t129 = __t55 * __v8;
            let __t76 = __t73 + __t26;
            let __t77 = __t74 + __t29;
            let __t92 = __t84 * __t54;
            let __t93 = __t86 * __t54;
            let __t94 = __t88 * __t54;
            let __t64 = __t63 * 0.5f64;
            let __t81 = __t78 * __t55;
            let __t95 = __t89 * __t66;
            let __t103 = __t84 * __t89;
            let __t110 = __t90 * __t67;
            let __t117 = __t86 * __t90;
            let __t122 = __t91 * __t48;
            let __t130 = __t88 * __t91;
            let __t133 = __t102 * __t55;
            let __t134 = __t92 * __t84;
            let __t141 = __t93 * __t86;
            let __t146 = __t129 * __t55;
            let __t147 = __t94 * __t88;
            let __t98 = __t89 * __t67;
            let __t100 = __t89 * __t48;
            let __t106 = __t86 * __t89;
            let __t108 = __t88 * __t89;
            let __t113 = __t90 * __t48;
            let __t115 = __t84 * __t90;
            let __t120 = __t88 * __t90;
            let __t125 = __t84 * __t91;
            let __t127 = __t86 * __t91;
            let __t137 = __t92 * __t86;
            let __t139 = __t92 * __t88;
            let __t144 = __t93 * __t88;
            let __t65 = __t64 - __t19;
            let __t79 = __t76 * __t55;
            let __t80 = __t77 * __t55;
            let __t82 = __t81 - __v9;
            let __t97 = __v7 - __t95;
            let __t105 = __t102 - __t103;
            let __t112 = __v7 - __t110;
            let __t119 = __t102 - __t117;
            let __t124 = __v8 - __t122;
            let __t132 = __t129 - __t130;
            let __t136 = __t133 - __t134;
            let __t143 = __t133 - __t141;
            let __t149 = __t146 - __t147;
            let __t99 = -__t98;
            let __t101 = -__t100;
            let __t107 = -__t106;
            let __t109 = -__t108;
            let __t114 = -__t113;
            let __t116 = -__t115;
            let __t121 = -__t120;
            let __t126 = -__t125;
            let __t128 = -__t127;
            let __t138 = -__t137;
            let __t140 = -__t139;
            let __t145 = -__t144;
            let __t150 = -__t55;
            __RouthBundle {
                routhian: __t65,
                psi_dot: __t55,
                dr_domega: __Vector3::new(__t76, __t77, __t78),
                dr_dgamma: __Vector3::new(__t79, __t80, __t82),
                dr_dp: __t150,
                d2r_domega2: __Matrix3::new(
                    __t97,
                    __t99,
                    __t101,
                    __t99,
                    __t112,
                    __t114,
                    __t101,
                    __t114,
                    __t124,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t105,
                    __t107,
                    __t109,
                    __t116,
                    __t119,
                    __t121,
                    __t126,
                    __t128,
                    __t132,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t136,
                    __t138,
                    __t140,
                    __t138,
                    __t143,
                    __t145,
                    __t140,
                    __t145,
                    __t149,
                ),
            }
        }
        #[inline]
        fn gyroscopic_system(
            &self,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __GyroscopicSystem {
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t47 = __t46 * __v7;
            let __t50 = __t47 + __t49;
            let __t54 = 1.0f64 / __t50;
            let __t151 = __t54 * __v6;
            let __t89 = __t54 * __t66;
            let __t90 = __t54 * __t67;
            let __t91 = __t54 * __t48;
            let __t158 = __t151 * __t66;
            let __t159 = __t151 * __t67;
            let __t160 = __t151 * __t48;
            let __t174 = __t151 * __v7;
            let __t202 = __t151 * __v8;
            let __t95 = __t89 * __t66;
            let __t110 = __t90 * __t67;
            let __t122 = __t91 * __t48;
            let __t161 = __t158 * __t151;
            let __t162 = __t159 * __t151;
            let __t163 = __t160 * __t151;
            let __t168 = __t158 * __t54;
            let __t170 = __t159 * __t54;
            let __t172 = __t160 * __t54;
            let __t175 = __t158 * __t89;
            let __t189 = __t159 * __t90;
            let __t248 = __t161 * __v3;
            let __t249 = __t162 * __v4;
            let __t164 = __t163 - __v9;
            let __t208 = __t168 * __t158;
            let __t223 = __t170 * __t159;
            let __t233 = __t172 * __t160;
            let __t207 = __t174 * __t151;
            let __t232 = __t202 * __t151;
            let __t178 = __t175 * (-2f64);
            let __t251 = __t249 + __t248;
            let __t250 = __t164 * __v5;
            let __t213 = __t208 * (-4f64);
            let __t226 = __t223 * (-4f64);
            let __t236 = __t233 * (-4f64);
            let __t191 = __t189 * (-2f64);
            let __t203 = __t160 * __t91;
            let __t215 = __t168 * __t159;
            let __t219 = __t168 * __t160;
            let __t228 = __t170 * __t160;
            let __t214 = __t213 + __t207;
            let __t227 = __t226 + __t207;
            let __t237 = __t236 + __t232;
            let __t252 = __t250 + __t251;
            let __t179 = __t178 + __t174;
            let __t192 = __t191 + __t174;
            let __t205 = __t203 * (-2f64);
            let __t257 = __t228 * __v5;
            let __t263 = __t228 * __v4;
            let __t272 = __t219 * __v5;
            let __t276 = __t228 * __v3;
            let __t254 = __t214 - __t252;
            let __t255 = __t227 - __t252;
            let __t256 = __t237 - __t252;
            let __t278 = __t215 * __v5;
            let __t286 = __t219 * __v4;
            let __t290 = __t215 * __v4;
            let __t299 = __t219 * __v3;
            let __t309 = __t215 * __v3;
            let __t206 = __t205 + __t202;
            let __t239 = __t192 + __t179;
            let __t258 = __t257 * (-4f64);
            let __t259 = __t256 * __v4;
            let __t262 = __t255 * __v5;
            let __t265 = __t263 * 4f64;
            let __t271 = __t256 * __v3;
            let __t274 = __t272 * 4f64;
            let __t277 = __t276 * (-4f64);
            let __t280 = __t278 * 4f64;
            let __t287 = __t286 * (-4f64);
            let __t288 = __t276 * 4f64;
            let __t291 = __t290 * (-4f64);
            let __t292 = __t255 * __v3;
            let __t300 = __t299 * (-4f64);
            let __t301 = __t254 * __v5;
            let __t308 = __t254 * __v4;
            let __t311 = __t309 * 4f64;
            let __t240 = __t239 + __t206;
            let __t261 = __t258 - __t259;
            let __t266 = __t265 + __t262;
            let __t275 = __t274 + __t271;
            let __t281 = __t280 + __t277;
            let __t289 = __t288 + __t287;
            let __t294 = __t291 - __t292;
            let __t303 = __t300 - __t301;
            let __t312 = __t311 + __t308;
            let __t241 = __t240 * 0.5f64;
            let __t267 = __t261 * __v4;
            let __t268 = __t266 * __v5;
            let __t282 = __t275 * __v4;
            let __t283 = __t281 * __v5;
            let __t295 = __t289 * __v4;
            let __t296 = __t294 * __v5;
            let __t304 = __t303 * __v5;
            let __t305 = __t275 * __v3;
            let __t313 = __t312 * __v5;
            let __t314 = __t289 * __v3;
            let __t317 = __t294 * __v3;
            let __t318 = __t312 * __v4;
            let __t98 = __t89 * __t67;
            let __t100 = __t89 * __t48;
            let __t113 = __t90 * __t48;
            let __t242 = __t241 * __v3;
            let __t243 = __t241 * __v4;
            let __t244 = __t241 * __v5;
            let __t97 = __v7 - __t95;
            let __t112 = __v7 - __t110;
            let __t124 = __v8 - __t122;
            let __t270 = __t267 - __t268;
            let __t285 = __t282 - __t283;
            let __t298 = __t295 - __t296;
            let __t307 = __t304 - __t305;
            let __t316 = __t313 - __t314;
            let __t320 = __t317 - __t318;
            let __t99 = -__t98;
            let __t101 = -__t100;
            let __t114 = -__t113;
            let __t245 = -__t242;
            let __t246 = -__t243;
            let __t247 = -__t244;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t97,
                    __t99,
                    __t101,
                    __t99,
                    __t112,
                    __t114,
                    __t101,
                    __t114,
                    __t124,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t247,
                    __t243,
                    __t244,
                    0f64,
                    __t245,
                    __t246,
                    __t242,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t270,
                    __t285,
                    __t298,
                    __t285,
                    __t307,
                    __t316,
                    __t298,
                    __t316,
                    __t320,
                ),
            }
        }
        #[inline]
        fn bundle_and_system(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> (__RouthBundle, __GyroscopicSystem) {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t19 = __v9 * __v5;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t69 = __t66 * 2f64;
            let __t71 = __t67 * 2f64;
            let __t72 = __t48 * 2f64;
            let __t47 = __t46 * __v7;
            let __t33 = __t26 * __v0;
            let __t34 = __t29 * __v1;
            let __t42 = __t40 + __t39;
            let __t16 = __t15 * __v2;
            let __t50 = __t47 + __t49;
            let __t35 = __t34 + __t33;
            let __t43 = __t42 + __t41;
            let __t54 = 1.0f64 / __t50;
            let __t36 = __t35 + __t16;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 * __t54;
            let __t89 = __t54 * __t66;
            let __t90 = __t54 * __t67;
            let __t91 = __t54 * __t48;
            let __t73 = __t55 * __t66;
            let __t74 = __t55 * __t67;
            let __t75 = __t55 * __t48;
            let __t83 = __t55 * __t69;
            let __t85 = __t55 * __t71;
            let __t87 = __t55 * __t72;
            let __t102 = __t55 * __v7;
            let __t129 = __t55 * __v8;
            let __t76 = __t73 + __t26;
            let __t77 = __t74 + __t29;
            let __t78 = __t75 + __t15;
            let __t84 = __t83 + __t26;
            let __t86 = __t85 + __t29;
            let __t88 = __t87 + __t15;
            let __t133 = __t102 * __t55;
            let __t146 = __t129 * __t55;
            let __t79 = __t76 * __t55;
            let __t80 = __t77 * __t55;
            let __t81 = __t78 * __t55;
            let __t92 = __t84 * __t54;
            let __t93 = __t86 * __t54;
            let __t94 = __t88 * __t54;
            let __t103 = __t84 * __t89;
            let __t117 = __t86 * __t90;
            let __t130 = __t88 * __t91;
            let __t57 = __t55 * __t53;
            let __t82 = __t81 - __v9;
            let __t134 = __t92 * __t84;
            let __t141 = __t93 * __t86;
            let __t147 = __t94 * __t88;
            let __t105 = __t102 - __t103;
            let __t119 = __t102 - __t117;
            let __t137 = __t92 * __t86;
            let __t139 = __t92 * __t88;
            let __t144 = __t93 * __t88;
            let __t136 = __t133 - __t134;
            let __t143 = __t133 - __t141;
            let __t149 = __t146 - __t147;
            let __t132 = __t129 - __t130;
            let __t63 = __t36 - __t57;
            let __t95 = __t89 * __t66;
            let __t110 = __t90 * __t67;
            let __t122 = __t91 * __t48;
            let __t98 = __t89 * __t67;
            let __t100 = __t89 * __t48;
            let __t106 = __t86 * __t89;
            let __t108 = __t88 * __t89;
            let __t64 = __t63 * 0.5f64;
            let __t113 = __t90 * __t48;
            let __t115 = __t84 * __t90;
            let __t120 = __t88 * __t90;
            let __t125 = __t84 * __t91;
            let __t127 = __t86 * __t91;
            let __t97 = __v7 - __t95;
            let __t112 = __v7 - __t110;
            let __t65 = __t64 - __t19;
            let __t124 = __v8 - __t122;
            let __t99 = -__t98;
            let __t101 = -__t100;
            let __t107 = -__t106;
            let __t109 = -__t108;
            let __t114 = -__t113;
            let __t116 = -__t115;
            let __t121 = -__t120;
            let __t126 = -__t125;
            let __t128 = -__t127;
            let __t138 = -__t137;
            let __t140 = -__t139;
            let __t145 = -__t144;
            let __t150 = -__t55;
            let __bundle = __RouthBundle {
                routhian: __t65,
                psi_dot: __t55,
                dr_domega: __Vector3::new(__t76, __t77, __t78),
                dr_dgamma: __Vector3::new(__t79, __t80, __t82),
                dr_dp: __t150,
                d2r_domega2: __Matrix3::new(
                    __t97,
                    __t99,
                    __t101,
                    __t99,
                    __t112,
                    __t114,
                    __t101,
                    __t114,
                    __t124,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t105,
                    __t107,
                    __t109,
                    __t116,
                    __t119,
                    __t121,
                    __t126,
                    __t128,
                    __t132,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t136,
                    __t138,
                    __t140,
                    __t138,
                    __t143,
                    __t145,
                    __t140,
                    __t145,
                    __t149,
                ),
            };
            let __t330 = __t79 * __v3;
            let __t331 = __t80 * __v4;
            let __t332 = __t82 * __v5;
            let __t321 = __t119 + __t105;
            let __t339 = __t144 * __v5;
            let __t346 = __t144 * __v4;
            let __t356 = __t139 * __v5;
            let __t371 = __t137 * __v4;
            let __t381 = __t139 * __v3;
            let __t333 = __t331 + __t330;
            let __t394 = __t137 * __v3;
            let __t359 = __t144 * __v3;
            let __t361 = __t137 * __v5;
            let __t368 = __t139 * __v4;
            let __t322 = __t321 + __t132;
            let __t334 = __t333 + __t332;
            let __t363 = __t361 - __t359;
            let __t370 = __t359 - __t368;
            let __t323 = __t322 * 0.5f64;
            let __t336 = __t136 - __t334;
            let __t337 = __t143 - __t334;
            let __t338 = __t149 - __t334;
            let __t365 = __t363 * __v5;
            let __t377 = __t370 * __v4;
            let __t398 = __t370 * __v3;
            let __t324 = __t323 * __v3;
            let __t325 = __t323 * __v4;
            let __t383 = __t336 * __v5;
            let __t345 = __t337 * __v5;
            let __t341 = __t338 * __v4;
            let __t355 = __t338 * __v3;
            let __t373 = __t337 * __v3;
            let __t393 = __t336 * __v4;
            let __t326 = __t323 * __v5;
            let __t327 = -__t324;
            let __t385 = __t383 + __t381;
            let __t348 = __t345 + __t346;
            let __t343 = __t341 + __t339;
            let __t358 = __t355 + __t356;
            let __t375 = __t373 + __t371;
            let __t396 = __t393 + __t394;
            let __t328 = -__t325;
            let __t329 = -__t326;
            let __t387 = __t385 * __v5;
            let __t351 = __t348 * __v5;
            let __t349 = __t343 * __v4;
            let __t389 = __t358 * __v3;
            let __t401 = __t375 * __v3;
            let __t403 = __t396 * __v4;
            let __t364 = __t358 * __v4;
            let __t378 = __t375 * __v5;
            let __t397 = __t396 * __v5;
            let __t353 = __t349 + __t351;
            let __t391 = __t389 + __t387;
            let __t405 = __t403 + __t401;
            let __t367 = __t364 - __t365;
            let __t380 = __t378 + __t377;
            let __t400 = __t397 - __t398;
            let __t354 = -__t353;
            let __t392 = -__t391;
            let __t406 = -__t405;
            (
                __bundle,
                __GyroscopicSystem {
                    a: __Matrix3::new(
                        __t97,
                        __t99,
                        __t101,
                        __t99,
                        __t112,
                        __t114,
                        __t101,
                        __t114,
                        __t124,
                    ),
                    g: __Matrix3::new(
                        0f64,
                        __t329,
                        __t325,
                        __t326,
                        0f64,
                        __t327,
                        __t328,
                        __t324,
                        0f64,
                    ),
                    c: __Matrix3::new(
                        __t354,
                        __t367,
                        __t380,
                        __t367,
                        __t392,
                        __t400,
                        __t380,
                        __t400,
                        __t406,
                    ),
                },
            )
        }
        #[inline]
        fn reduced_equations(
            &self,
            __big_omega: &__Vector3,
            __gamma: &__Vector3,
            __p_psi: __F64,
        ) -> __ReducedEquations {
            let __v0: __F64 = __big_omega[0usize];
            let __v1: __F64 = __big_omega[1usize];
            let __v2: __F64 = __big_omega[2usize];
            let __v3: __F64 = __gamma[0usize];
            let __v4: __F64 = __gamma[1usize];
            let __v5: __F64 = __gamma[2usize];
            let __v6: __F64 = __p_psi;
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __v9: __F64 = self.mgl;
            let __t44 = __v3 * __v3;
            let __t45 = __v4 * __v4;
            let __t48 = __v8 * __v5;
            let __t26 = __v7 * __v0;
            let __t29 = __v7 * __v1;
            let __t15 = __v8 * __v2;
            let __t66 = __v7 * __v3;
            let __t67 = __v7 * __v4;
            let __t661 = __v4 * __v2;
            let __t46 = __t45 + __t44;
            let __t49 = __t48 * __v5;
            let __t39 = __t26 * __v3;
            let __t40 = __t29 * __v4;
            let __t41 = __t15 * __v5;
            let __t69 = __t66 * 2f64;
            let __t71 = __t67 * 2f64;
            let __t72 = __t48 * 2f64;
            let __t47 = __t46 * __v7;
            let __t662 = __v5 * __v1;
            let __t665 = __v5 * __v0;
            let __t42 = __t40 + __t39;
            let __t666 = __v3 * __v2;
            let __t669 = __v3 * __v1;
            let __t670 = __v4 * __v0;
            let __t50 = __t47 + __t49;
            let __t664 = __t661 - __t662;
            let __t43 = __t42 + __t41;
            let __t668 = __t665 - __t666;
            let __t672 = __t669 - __t670;
            let __t54 = 1.0f64 / __t50;
            let __t53 = __v6 - __t43;
            let __t55 = __t53 * __t54;
            let __t89 = __t54 * __t66;
            let __t90 = __t54 * __t67;
            let __t91 = __t54 * __t48;
            let __t75 = __t55 * __t48;
            let __t83 = __t55 * __t69;
            let __t85 = __t55 * __t71;
            let __t73 = __t55 * __t66;
            let __t74 = __t55 * __t67;
            let __t87 = __t55 * __t72;
            let __t102 = __t55 * __v7;
            let __t129 = __t55 * __v8;
            let __t78 = __t75 + __t15;
            let __t84 = __t83 + __t26;
            let __t86 = __t85 + __t29;
            let __t76 = __t73 + __t26;
            let __t77 = __t74 + __t29;
            let __t88 = __t87 + __t15;
            let __t81 = __t78 * __t55;
            let __t103 = __t84 * __t89;
            let __t117 = __t86 * __t90;
            let __t79 = __t76 * __t55;
            let __t80 = __t77 * __t55;
            let __t106 = __t86 * __t89;
            let __t115 = __t84 * __t90;
            let __t125 = __t84 * __t91;
            let __t82 = __t81 - __v9;
            let __t105 = __t102 - __t103;
            let __t119 = __t102 - __t117;
            let __t127 = __t86 * __t91;
            let __t130 = __t88 * __t91;
            let __t108 = __t88 * __t89;
            let __t120 = __t88 * __t90;
            let __t692 = __t106 * __t668;
            let __t698 = __t115 * __t664;
            let __t691 = __t105 * __t664;
            let __t700 = __t119 * __t668;
            let __t705 = __t125 * __t664;
            let __t132 = __t129 - __t130;
            let __t707 = __t127 * __t668;
            let __t713 = __t77 * __v2;
            let __t714 = __t78 * __v1;
            let __t717 = __t78 * __v0;
            let __t718 = __t76 * __v2;
            let __t721 = __t76 * __v1;
            let __t722 = __t77 * __v0;
            let __t725 = __t80 * __v5;
            let __t726 = __t82 * __v4;
            let __t729 = __t82 * __v3;
            let __t730 = __t79 * __v5;
            let __t733 = __t79 * __v4;
            let __t734 = __t80 * __v3;
            let __t694 = __t108 * __t672;
            let __t696 = __t691 - __t692;
            let __t701 = __t120 * __t672;
            let __t703 = __t700 - __t698;
            let __t709 = __t132 * __t672;
            let __t710 = __t707 + __t705;
            let __t716 = __t713 - __t714;
            let __t720 = __t717 - __t718;
            let __t724 = __t721 - __t722;
            let __t728 = __t725 - __t726;
            let __t732 = __t729 - __t730;
            let __t736 = __t733 - __t734;
            let __t697 = __t696 - __t694;
            let __t704 = __t703 - __t701;
            let __t712 = __t709 - __t710;
            let __t737 = __t728 + __t716;
            let __t740 = __t732 + __t720;
            let __t743 = __t736 + __t724;
            let __t739 = __t737 - __t697;
            let __t742 = __t740 - __t704;
            let __t745 = __t743 - __t712;
            __ReducedEquations {
                inertia: __Matrix3::new(
                    __v7,
                    0f64,
                    0f64,
                    0f64,
                    __v7,
                    0f64,
                    0f64,
                    0f64,
                    __v8,
                ),
                right_side: __Vector3::new(__t739, __t742, __t745),
                psi_dot: __t55,
                rank_one: __MaybeRankOne::None,
            }
        }
        #[inline]
        fn certification_tape(&self) -> __MaybeTape {
            static __CERTIFICATION_OPS: [__Op; 49] = [
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::PPsi,
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Neg(6),
                __Op::Powi(0, 2),
                __Op::Powi(1, 2),
                __Op::Add(8, 9),
                __Op::Mul(4, 10),
                __Op::Mul(2, 5),
                __Op::Mul(2, 12),
                __Op::Add(11, 13),
                __Op::Recip(14),
                __Op::Mul(0, 4),
                __Op::Mul(1, 4),
                __Op::Mul(3, 15),
                __Op::Mul(16, 18),
                __Op::Mul(17, 18),
                __Op::Mul(12, 18),
                __Op::Mul(18, 19),
                __Op::Mul(18, 20),
                __Op::Mul(18, 21),
                __Op::Add(7, 24),
                __Op::Mul(15, 19),
                __Op::Mul(15, 20),
                __Op::Mul(15, 21),
                __Op::Mul(4, 18),
                __Op::Mul(5, 18),
                __Op::Mul(18, 29),
                __Op::Mul(19, 26),
                __Op::Const(0xc010000000000000),
                __Op::Mul(33, 32),
                __Op::Add(31, 34),
                __Op::Mul(20, 26),
                __Op::Mul(33, 36),
                __Op::Mul(21, 26),
                __Op::Mul(33, 38),
                __Op::Mul(20, 27),
                __Op::Mul(33, 40),
                __Op::Add(31, 41),
                __Op::Mul(21, 27),
                __Op::Mul(33, 43),
                __Op::Mul(18, 30),
                __Op::Mul(21, 28),
                __Op::Mul(33, 46),
                __Op::Add(45, 47),
            ];
            static __CERTIFICATION_OUT: [__Output; 9] = [
                __Output {
                    name: "dr_dgamma[0]",
                    slot: 22,
                },
                __Output {
                    name: "dr_dgamma[1]",
                    slot: 23,
                },
                __Output {
                    name: "dr_dgamma[2]",
                    slot: 25,
                },
                __Output {
                    name: "d2r_dgamma2[0][0]",
                    slot: 35,
                },
                __Output {
                    name: "d2r_dgamma2[0][1]",
                    slot: 37,
                },
                __Output {
                    name: "d2r_dgamma2[0][2]",
                    slot: 39,
                },
                __Output {
                    name: "d2r_dgamma2[1][1]",
                    slot: 42,
                },
                __Output {
                    name: "d2r_dgamma2[1][2]",
                    slot: 44,
                },
                __Output {
                    name: "d2r_dgamma2[2][2]",
                    slot: 48,
                },
            ];
            static __CERTIFICATION: __Tape = __Tape::from_static(
                &__CERTIFICATION_OPS,
                &__CERTIFICATION_OUT,
                3,
            );
            __CertificationTape::new(
                    __Tape::clone(&__CERTIFICATION),
                    <[__F64]>::to_vec(&[self.a1, self.c, self.mgl]),
                )
                .ok()
        }
        #[inline]
        fn routh_tape(&self) -> __MaybeRouthianTape {
            static __ROUTHIAN_OPS: [__Op; 42] = [
                __Op::Omega(0),
                __Op::Omega(1),
                __Op::Omega(2),
                __Op::Gamma(0),
                __Op::Gamma(1),
                __Op::Gamma(2),
                __Op::PPsi,
                __Op::Param(0),
                __Op::Param(1),
                __Op::Param(2),
                __Op::Const(0x3fe0000000000000),
                __Op::Mul(2, 8),
                __Op::Mul(2, 11),
                __Op::Mul(5, 9),
                __Op::Neg(13),
                __Op::Mul(0, 7),
                __Op::Mul(1, 7),
                __Op::Mul(0, 15),
                __Op::Mul(1, 16),
                __Op::Add(17, 18),
                __Op::Add(12, 19),
                __Op::Mul(3, 15),
                __Op::Mul(4, 16),
                __Op::Mul(5, 11),
                __Op::Add(21, 22),
                __Op::Add(23, 24),
                __Op::Powi(3, 2),
                __Op::Powi(4, 2),
                __Op::Add(26, 27),
                __Op::Mul(7, 28),
                __Op::Mul(5, 8),
                __Op::Mul(5, 30),
                __Op::Add(29, 31),
                __Op::Neg(25),
                __Op::Add(6, 33),
                __Op::Recip(32),
                __Op::Mul(34, 35),
                __Op::Mul(34, 36),
                __Op::Neg(37),
                __Op::Add(20, 38),
                __Op::Mul(10, 39),
                __Op::Add(14, 40),
            ];
            static __ROUTHIAN_OUT: [__Output; 1] = [
                __Output {
                    name: "routhian",
                    slot: 41,
                },
            ];
            static __ROUTHIAN: __Tape = __Tape::from_static(
                &__ROUTHIAN_OPS,
                &__ROUTHIAN_OUT,
                3,
            );
            __RouthianTape::new(
                    __Tape::clone(&__ROUTHIAN),
                    <[__F64]>::to_vec(&[self.a1, self.c, self.mgl]),
                )
                .ok()
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for LagrangeTop {
        const LAGRANGIAN: &'static str = "0.5·(a1·(ω₁^2 + ω₂^2) + ω₃^2·c) - γ₃·mgl";
        const AMENDED_POTENTIAL: &'static str = "γ₃·mgl + 0.5·p_ψ^2 / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
        const PSI_DOT_AT_REST: &'static str = "p_ψ / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
        fn latex(&self) -> ::routh::__private::LatexFormulas {
            static __LATEX: ::routh::__private::DerivedLatex = ::routh::__private::DerivedLatex::new(
                "# [lagrangian (kinetic = 0.5 * (a1 * (omega . x * omega . x + omega . y * omega . y) + c * omega . z * omega . z) , potential = mgl * gamma . z ,)] pub struct LagrangeTop { pub a1 : f64 , pub c : f64 , pub mgl : f64 , }",
            );
            __LATEX.get()
        }
    }
};
