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
    type __ReducedEquations = ::routh::__private::ReducedEquations;
    type __RouthTape = ::routh::__private::RouthTape;
    type __MaybeTape = ::routh::__private::MaybeTape;
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
            let __t11: __F64 = __v0 * __v0;
            let __t12: __F64 = __v1 * __v1;
            let __t13: __F64 = __t11 + __t12;
            let __t14: __F64 = __v7 * __t13;
            let __t15: __F64 = __v2 * __v8;
            let __t16: __F64 = __v2 * __t15;
            let __t17: __F64 = __t14 + __t16;
            let __t18: __F64 = 0.5f64 * __t17;
            let __t19: __F64 = __v5 * __v9;
            let __t22: __F64 = __t18 - __t19;
            __t22
        }
        #[inline]
        fn dl_domega(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v0: __F64 = __omega[0usize];
            let __v1: __F64 = __omega[1usize];
            let __v2: __F64 = __omega[2usize];
            let __v7: __F64 = self.a1;
            let __v8: __F64 = self.c;
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            __Vector3::new(__t26, __t29, __t15)
        }
        #[inline]
        fn dl_dgamma(&self, __omega: &__Vector3, __gamma: &__Vector3) -> __Vector3 {
            let __v9: __F64 = self.mgl;
            let __t32: __F64 = -__v9;
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
            let __t11: __F64 = __v0 * __v0;
            let __t12: __F64 = __v1 * __v1;
            let __t13: __F64 = __t11 + __t12;
            let __t14: __F64 = __v7 * __t13;
            let __t15: __F64 = __v2 * __v8;
            let __t16: __F64 = __v2 * __t15;
            let __t17: __F64 = __t14 + __t16;
            let __t18: __F64 = 0.5f64 * __t17;
            let __t19: __F64 = __v5 * __v9;
            let __t22: __F64 = __t18 - __t19;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t33: __F64 = __v0 * __t26;
            let __t34: __F64 = __v1 * __t29;
            let __t35: __F64 = __t33 + __t34;
            let __t36: __F64 = __t16 + __t35;
            let __t38: __F64 = __t36 - __t22;
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t510: __F64 = __v2 * __t29;
            let __t511: __F64 = __v1 * __t15;
            let __t513: __F64 = __t510 - __t511;
            let __t514: __F64 = __v0 * __t15;
            let __t515: __F64 = __v2 * __t26;
            let __t517: __F64 = __t514 - __t515;
            let __t518: __F64 = __v1 * __t26;
            let __t519: __F64 = __v0 * __t29;
            let __t521: __F64 = __t518 - __t519;
            let __t522: __F64 = __v4 * __v9;
            let __t524: __F64 = __v3 * __v9;
            let __t526: __F64 = __t513 + __t522;
            let __t527: __F64 = __t517 - __t524;
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
                right_side: __Vector3::new(__t526, __t527, __t521),
            }
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t55: __F64 = __t53 / __t50;
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
            let __t11: __F64 = __v0 * __v0;
            let __t12: __F64 = __v1 * __v1;
            let __t13: __F64 = __t11 + __t12;
            let __t14: __F64 = __v7 * __t13;
            let __t15: __F64 = __v2 * __v8;
            let __t16: __F64 = __v2 * __t15;
            let __t17: __F64 = __t14 + __t16;
            let __t18: __F64 = 0.5f64 * __t17;
            let __t19: __F64 = __v5 * __v9;
            let __t22: __F64 = __t18 - __t19;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t55: __F64 = __t53 / __t50;
            let __t57: __F64 = __t53 * __t55;
            let __t60: __F64 = (-0.5f64) * __t57;
            let __t61: __F64 = __t22 + __t60;
            __t61
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t55: __F64 = __t53 / __t50;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t69: __F64 = __t55 * __t62;
            let __t70: __F64 = __t55 * __t63;
            let __t71: __F64 = __t48 * __t55;
            let __t72: __F64 = __t26 + __t69;
            let __t73: __F64 = __t29 + __t70;
            let __t74: __F64 = __t15 + __t71;
            __Vector3::new(__t72, __t73, __t74)
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t55: __F64 = __t53 / __t50;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t69: __F64 = __t55 * __t62;
            let __t70: __F64 = __t55 * __t63;
            let __t71: __F64 = __t48 * __t55;
            let __t72: __F64 = __t26 + __t69;
            let __t73: __F64 = __t29 + __t70;
            let __t74: __F64 = __t15 + __t71;
            let __t75: __F64 = __t55 * __t72;
            let __t76: __F64 = __t55 * __t73;
            let __t77: __F64 = __t55 * __t74;
            let __t78: __F64 = __t77 - __v9;
            __Vector3::new(__t75, __t76, __t78)
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t55: __F64 = __t53 / __t50;
            let __t146: __F64 = -__t55;
            __t146
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
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t54: __F64 = 1.0f64 / __t50;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t85: __F64 = __t54 * __t62;
            let __t86: __F64 = __t54 * __t63;
            let __t87: __F64 = __t48 * __t54;
            let __t91: __F64 = __t62 * __t85;
            let __t93: __F64 = __v7 - __t91;
            let __t94: __F64 = __t63 * __t85;
            let __t95: __F64 = -__t94;
            let __t96: __F64 = __t48 * __t85;
            let __t97: __F64 = -__t96;
            let __t106: __F64 = __t63 * __t86;
            let __t108: __F64 = __v7 - __t106;
            let __t109: __F64 = __t48 * __t86;
            let __t110: __F64 = -__t109;
            let __t118: __F64 = __t48 * __t87;
            let __t120: __F64 = __v8 - __t118;
            __Matrix3::new(
                __t93,
                __t95,
                __t97,
                __t95,
                __t108,
                __t110,
                __t97,
                __t110,
                __t120,
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t54: __F64 = 1.0f64 / __t50;
            let __t55: __F64 = __t53 * __t54;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t69: __F64 = __t55 * __t62;
            let __t70: __F64 = __t55 * __t63;
            let __t71: __F64 = __t48 * __t55;
            let __t79: __F64 = 2f64 * __t69;
            let __t80: __F64 = __t26 + __t79;
            let __t81: __F64 = 2f64 * __t70;
            let __t82: __F64 = __t29 + __t81;
            let __t83: __F64 = 2f64 * __t71;
            let __t84: __F64 = __t15 + __t83;
            let __t85: __F64 = __t54 * __t62;
            let __t86: __F64 = __t54 * __t63;
            let __t87: __F64 = __t48 * __t54;
            let __t98: __F64 = __v7 * __t55;
            let __t99: __F64 = __t80 * __t85;
            let __t101: __F64 = __t98 - __t99;
            let __t102: __F64 = __t82 * __t85;
            let __t103: __F64 = -__t102;
            let __t104: __F64 = __t84 * __t85;
            let __t105: __F64 = -__t104;
            let __t111: __F64 = __t80 * __t86;
            let __t112: __F64 = -__t111;
            let __t113: __F64 = __t82 * __t86;
            let __t115: __F64 = __t98 - __t113;
            let __t116: __F64 = __t84 * __t86;
            let __t117: __F64 = -__t116;
            let __t121: __F64 = __t80 * __t87;
            let __t122: __F64 = -__t121;
            let __t123: __F64 = __t82 * __t87;
            let __t124: __F64 = -__t123;
            let __t125: __F64 = __v8 * __t55;
            let __t126: __F64 = __t84 * __t87;
            let __t128: __F64 = __t125 - __t126;
            __Matrix3::new(
                __t101,
                __t103,
                __t105,
                __t112,
                __t115,
                __t117,
                __t122,
                __t124,
                __t128,
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t54: __F64 = 1.0f64 / __t50;
            let __t55: __F64 = __t53 * __t54;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t69: __F64 = __t55 * __t62;
            let __t70: __F64 = __t55 * __t63;
            let __t71: __F64 = __t48 * __t55;
            let __t79: __F64 = 2f64 * __t69;
            let __t80: __F64 = __t26 + __t79;
            let __t81: __F64 = 2f64 * __t70;
            let __t82: __F64 = __t29 + __t81;
            let __t83: __F64 = 2f64 * __t71;
            let __t84: __F64 = __t15 + __t83;
            let __t88: __F64 = __t54 * __t80;
            let __t89: __F64 = __t54 * __t82;
            let __t90: __F64 = __t54 * __t84;
            let __t98: __F64 = __v7 * __t55;
            let __t125: __F64 = __v8 * __t55;
            let __t129: __F64 = __t55 * __t98;
            let __t130: __F64 = __t80 * __t88;
            let __t132: __F64 = __t129 - __t130;
            let __t133: __F64 = __t82 * __t88;
            let __t134: __F64 = -__t133;
            let __t135: __F64 = __t84 * __t88;
            let __t136: __F64 = -__t135;
            let __t137: __F64 = __t82 * __t89;
            let __t139: __F64 = __t129 - __t137;
            let __t140: __F64 = __t84 * __t89;
            let __t141: __F64 = -__t140;
            let __t142: __F64 = __t55 * __t125;
            let __t143: __F64 = __t84 * __t90;
            let __t145: __F64 = __t142 - __t143;
            __Matrix3::new(
                __t132,
                __t134,
                __t136,
                __t134,
                __t139,
                __t141,
                __t136,
                __t141,
                __t145,
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
            let __t19: __F64 = __v5 * __v9;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t147: __F64 = __v6 / __t50;
            let __t149: __F64 = __v6 * __t147;
            let __t151: __F64 = (-0.5f64) * __t149;
            let __t152: __F64 = __t151 - __t19;
            let __t233: __F64 = -__t152;
            __t233
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
            let __t11: __F64 = __v0 * __v0;
            let __t12: __F64 = __v1 * __v1;
            let __t13: __F64 = __t11 + __t12;
            let __t14: __F64 = __v7 * __t13;
            let __t15: __F64 = __v2 * __v8;
            let __t16: __F64 = __v2 * __t15;
            let __t17: __F64 = __t14 + __t16;
            let __t18: __F64 = 0.5f64 * __t17;
            let __t19: __F64 = __v5 * __v9;
            let __t22: __F64 = __t18 - __t19;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t54: __F64 = 1.0f64 / __t50;
            let __t55: __F64 = __t53 * __t54;
            let __t57: __F64 = __t53 * __t55;
            let __t60: __F64 = (-0.5f64) * __t57;
            let __t61: __F64 = __t22 + __t60;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t69: __F64 = __t55 * __t62;
            let __t70: __F64 = __t55 * __t63;
            let __t71: __F64 = __t48 * __t55;
            let __t72: __F64 = __t26 + __t69;
            let __t73: __F64 = __t29 + __t70;
            let __t74: __F64 = __t15 + __t71;
            let __t75: __F64 = __t55 * __t72;
            let __t76: __F64 = __t55 * __t73;
            let __t77: __F64 = __t55 * __t74;
            let __t78: __F64 = __t77 - __v9;
            let __t79: __F64 = 2f64 * __t69;
            let __t80: __F64 = __t26 + __t79;
            let __t81: __F64 = 2f64 * __t70;
            let __t82: __F64 = __t29 + __t81;
            let __t83: __F64 = 2f64 * __t71;
            let __t84: __F64 = __t15 + __t83;
            let __t85: __F64 = __t54 * __t62;
            let __t86: __F64 = __t54 * __t63;
            let __t87: __F64 = __t48 * __t54;
            let __t88: __F64 = __t54 * __t80;
            let __t89: __F64 = __t54 * __t82;
            let __t90: __F64 = __t54 * __t84;
            let __t91: __F64 = __t62 * __t85;
            let __t93: __F64 = __v7 - __t91;
            let __t94: __F64 = __t63 * __t85;
            let __t95: __F64 = -__t94;
            let __t96: __F64 = __t48 * __t85;
            let __t97: __F64 = -__t96;
            let __t98: __F64 = __v7 * __t55;
            let __t99: __F64 = __t80 * __t85;
            let __t101: __F64 = __t98 - __t99;
            let __t102: __F64 = __t82 * __t85;
            let __t103: __F64 = -__t102;
            let __t104: __F64 = __t84 * __t85;
            let __t105: __F64 = -__t104;
            let __t106: __F64 = __t63 * __t86;
            let __t108: __F64 = __v7 - __t106;
            let __t109: __F64 = __t48 * __t86;
            let __t110: __F64 = -__t109;
            let __t111: __F64 = __t80 * __t86;
            let __t112: __F64 = -__t111;
            let __t113: __F64 = __t82 * __t86;
            let __t115: __F64 = __t98 - __t113;
            let __t116: __F64 = __t84 * __t86;
            let __t117: __F64 = -__t116;
            let __t118: __F64 = __t48 * __t87;
            let __t120: __F64 = __v8 - __t118;
            let __t121: __F64 = __t80 * __t87;
            let __t122: __F64 = -__t121;
            let __t123: __F64 = __t82 * __t87;
            let __t124: __F64 = -__t123;
            let __t125: __F64 = __v8 * __t55;
            let __t126: __F64 = __t84 * __t87;
            let __t128: __F64 = __t125 - __t126;
            let __t129: __F64 = __t55 * __t98;
            let __t130: __F64 = __t80 * __t88;
            let __t132: __F64 = __t129 - __t130;
            let __t133: __F64 = __t82 * __t88;
            let __t134: __F64 = -__t133;
            let __t135: __F64 = __t84 * __t88;
            let __t136: __F64 = -__t135;
            let __t137: __F64 = __t82 * __t89;
            let __t139: __F64 = __t129 - __t137;
            let __t140: __F64 = __t84 * __t89;
            let __t141: __F64 = -__t140;
            let __t142: __F64 = __t55 * __t125;
            let __t143: __F64 = __t84 * __t90;
            let __t145: __F64 = __t142 - __t143;
            let __t146: __F64 = -__t55;
            __RouthBundle {
                routhian: __t61,
                psi_dot: __t55,
                dr_domega: __Vector3::new(__t72, __t73, __t74),
                dr_dgamma: __Vector3::new(__t75, __t76, __t78),
                dr_dp: __t146,
                d2r_domega2: __Matrix3::new(
                    __t93,
                    __t95,
                    __t97,
                    __t95,
                    __t108,
                    __t110,
                    __t97,
                    __t110,
                    __t120,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t101,
                    __t103,
                    __t105,
                    __t112,
                    __t115,
                    __t117,
                    __t122,
                    __t124,
                    __t128,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t132,
                    __t134,
                    __t136,
                    __t134,
                    __t139,
                    __t141,
                    __t136,
                    __t141,
                    __t145,
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
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t54: __F64 = 1.0f64 / __t50;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t85: __F64 = __t54 * __t62;
            let __t86: __F64 = __t54 * __t63;
            let __t87: __F64 = __t48 * __t54;
            let __t91: __F64 = __t62 * __t85;
            let __t93: __F64 = __v7 - __t91;
            let __t94: __F64 = __t63 * __t85;
            let __t95: __F64 = -__t94;
            let __t96: __F64 = __t48 * __t85;
            let __t97: __F64 = -__t96;
            let __t106: __F64 = __t63 * __t86;
            let __t108: __F64 = __v7 - __t106;
            let __t109: __F64 = __t48 * __t86;
            let __t110: __F64 = -__t109;
            let __t118: __F64 = __t48 * __t87;
            let __t120: __F64 = __v8 - __t118;
            let __t147: __F64 = __v6 * __t54;
            let __t153: __F64 = __t62 * __t147;
            let __t154: __F64 = __t63 * __t147;
            let __t155: __F64 = __t48 * __t147;
            let __t156: __F64 = __t147 * __t153;
            let __t157: __F64 = __t147 * __t154;
            let __t158: __F64 = __t147 * __t155;
            let __t159: __F64 = __t158 - __v9;
            let __t163: __F64 = __t54 * __t153;
            let __t165: __F64 = __t54 * __t154;
            let __t167: __F64 = __t54 * __t155;
            let __t169: __F64 = __v7 * __t147;
            let __t170: __F64 = __t85 * __t153;
            let __t173: __F64 = (-2f64) * __t170;
            let __t174: __F64 = __t169 + __t173;
            let __t184: __F64 = __t86 * __t154;
            let __t186: __F64 = (-2f64) * __t184;
            let __t187: __F64 = __t169 + __t186;
            let __t197: __F64 = __v8 * __t147;
            let __t198: __F64 = __t87 * __t155;
            let __t200: __F64 = (-2f64) * __t198;
            let __t201: __F64 = __t197 + __t200;
            let __t202: __F64 = __t147 * __t169;
            let __t203: __F64 = __t153 * __t163;
            let __t208: __F64 = (-4f64) * __t203;
            let __t209: __F64 = __t202 + __t208;
            let __t210: __F64 = __t154 * __t163;
            let __t214: __F64 = __t155 * __t163;
            let __t218: __F64 = __t154 * __t165;
            let __t221: __F64 = (-4f64) * __t218;
            let __t222: __F64 = __t202 + __t221;
            let __t223: __F64 = __t155 * __t165;
            let __t227: __F64 = __t147 * __t197;
            let __t228: __F64 = __t155 * __t167;
            let __t231: __F64 = (-4f64) * __t228;
            let __t232: __F64 = __t227 + __t231;
            let __t237: __F64 = __t174 + __t187;
            let __t238: __F64 = __t201 + __t237;
            let __t240: __F64 = __v5 * __t238;
            let __t241: __F64 = 0.5f64 * __t240;
            let __t242: __F64 = (-0.5f64) * __t240;
            let __t243: __F64 = __v4 * __t238;
            let __t244: __F64 = 0.5f64 * __t243;
            let __t245: __F64 = __v3 * __t238;
            let __t246: __F64 = 0.5f64 * __t245;
            let __t247: __F64 = (-0.5f64) * __t245;
            let __t248: __F64 = (-0.5f64) * __t243;
            let __t249: __F64 = __v3 * __t156;
            let __t250: __F64 = __v4 * __t157;
            let __t251: __F64 = __v5 * __t159;
            let __t252: __F64 = __t249 + __t250;
            let __t253: __F64 = __t251 + __t252;
            let __t255: __F64 = __t253 - __t209;
            let __t257: __F64 = __t253 - __t222;
            let __t259: __F64 = __t253 - __t232;
            let __t260: __F64 = __v5 * __t210;
            let __t261: __F64 = 4f64 * __t260;
            let __t262: __F64 = __v4 * __t214;
            let __t264: __F64 = (-4f64) * __t262;
            let __t265: __F64 = __t261 + __t264;
            let __t266: __F64 = __v5 * __t257;
            let __t267: __F64 = __v4 * __t223;
            let __t269: __F64 = (-4f64) * __t267;
            let __t270: __F64 = __t266 + __t269;
            let __t271: __F64 = __v5 * __t223;
            let __t272: __F64 = 4f64 * __t271;
            let __t273: __F64 = __v4 * __t259;
            let __t275: __F64 = __t272 - __t273;
            let __t276: __F64 = __v5 * __t255;
            let __t278: __F64 = __v3 * __t214;
            let __t279: __F64 = 4f64 * __t278;
            let __t280: __F64 = __t279 - __t276;
            let __t281: __F64 = (-4f64) * __t260;
            let __t282: __F64 = __v3 * __t223;
            let __t283: __F64 = 4f64 * __t282;
            let __t284: __F64 = __t281 + __t283;
            let __t285: __F64 = __v5 * __t214;
            let __t287: __F64 = (-4f64) * __t285;
            let __t288: __F64 = __v3 * __t259;
            let __t289: __F64 = __t287 + __t288;
            let __t290: __F64 = __v4 * __t255;
            let __t291: __F64 = __v3 * __t210;
            let __t293: __F64 = (-4f64) * __t291;
            let __t294: __F64 = __t290 + __t293;
            let __t295: __F64 = __v4 * __t210;
            let __t296: __F64 = 4f64 * __t295;
            let __t297: __F64 = __v3 * __t257;
            let __t299: __F64 = __t296 - __t297;
            let __t302: __F64 = __v5 * __t270;
            let __t303: __F64 = __v4 * __t275;
            let __t305: __F64 = __t302 - __t303;
            let __t306: __F64 = __v5 * __t265;
            let __t308: __F64 = __v3 * __t275;
            let __t309: __F64 = __t308 - __t306;
            let __t310: __F64 = __v4 * __t265;
            let __t311: __F64 = __v3 * __t270;
            let __t313: __F64 = __t310 - __t311;
            let __t314: __F64 = __v5 * __t280;
            let __t316: __F64 = __v3 * __t289;
            let __t317: __F64 = __t316 - __t314;
            let __t318: __F64 = __v4 * __t280;
            let __t319: __F64 = __v3 * __t284;
            let __t321: __F64 = __t318 - __t319;
            let __t322: __F64 = __v4 * __t294;
            let __t323: __F64 = __v3 * __t299;
            let __t325: __F64 = __t322 - __t323;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t93,
                    __t95,
                    __t97,
                    __t95,
                    __t108,
                    __t110,
                    __t97,
                    __t110,
                    __t120,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t242,
                    __t244,
                    __t241,
                    0f64,
                    __t247,
                    __t248,
                    __t246,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t305,
                    __t309,
                    __t313,
                    __t309,
                    __t317,
                    __t321,
                    __t313,
                    __t321,
                    __t325,
                ),
            }
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
            let __t15: __F64 = __v2 * __v8;
            let __t26: __F64 = __v0 * __v7;
            let __t29: __F64 = __v1 * __v7;
            let __t39: __F64 = __v3 * __t26;
            let __t40: __F64 = __v4 * __t29;
            let __t41: __F64 = __v5 * __t15;
            let __t42: __F64 = __t39 + __t40;
            let __t43: __F64 = __t41 + __t42;
            let __t44: __F64 = __v3 * __v3;
            let __t45: __F64 = __v4 * __v4;
            let __t46: __F64 = __t44 + __t45;
            let __t47: __F64 = __v7 * __t46;
            let __t48: __F64 = __v5 * __v8;
            let __t49: __F64 = __v5 * __t48;
            let __t50: __F64 = __t47 + __t49;
            let __t53: __F64 = __v6 - __t43;
            let __t54: __F64 = 1.0f64 / __t50;
            let __t55: __F64 = __t53 * __t54;
            let __t62: __F64 = __v3 * __v7;
            let __t63: __F64 = __v4 * __v7;
            let __t69: __F64 = __t55 * __t62;
            let __t70: __F64 = __t55 * __t63;
            let __t71: __F64 = __t48 * __t55;
            let __t72: __F64 = __t26 + __t69;
            let __t73: __F64 = __t29 + __t70;
            let __t74: __F64 = __t15 + __t71;
            let __t75: __F64 = __t55 * __t72;
            let __t76: __F64 = __t55 * __t73;
            let __t77: __F64 = __t55 * __t74;
            let __t78: __F64 = __t77 - __v9;
            let __t79: __F64 = 2f64 * __t69;
            let __t80: __F64 = __t26 + __t79;
            let __t81: __F64 = 2f64 * __t70;
            let __t82: __F64 = __t29 + __t81;
            let __t83: __F64 = 2f64 * __t71;
            let __t84: __F64 = __t15 + __t83;
            let __t85: __F64 = __t54 * __t62;
            let __t86: __F64 = __t54 * __t63;
            let __t87: __F64 = __t48 * __t54;
            let __t98: __F64 = __v7 * __t55;
            let __t99: __F64 = __t80 * __t85;
            let __t101: __F64 = __t98 - __t99;
            let __t102: __F64 = __t82 * __t85;
            let __t104: __F64 = __t84 * __t85;
            let __t111: __F64 = __t80 * __t86;
            let __t113: __F64 = __t82 * __t86;
            let __t115: __F64 = __t98 - __t113;
            let __t116: __F64 = __t84 * __t86;
            let __t121: __F64 = __t80 * __t87;
            let __t123: __F64 = __t82 * __t87;
            let __t125: __F64 = __v8 * __t55;
            let __t126: __F64 = __t84 * __t87;
            let __t128: __F64 = __t125 - __t126;
            let __t498: __F64 = __v2 * __v4;
            let __t499: __F64 = __v1 * __v5;
            let __t501: __F64 = __t498 - __t499;
            let __t502: __F64 = __v0 * __v5;
            let __t503: __F64 = __v2 * __v3;
            let __t505: __F64 = __t502 - __t503;
            let __t506: __F64 = __v1 * __v3;
            let __t507: __F64 = __v0 * __v4;
            let __t509: __F64 = __t506 - __t507;
            let __t528: __F64 = __t101 * __t501;
            let __t529: __F64 = __t102 * __t505;
            let __t531: __F64 = __t104 * __t509;
            let __t533: __F64 = __t528 - __t529;
            let __t534: __F64 = __t533 - __t531;
            let __t535: __F64 = __t111 * __t501;
            let __t537: __F64 = __t115 * __t505;
            let __t538: __F64 = __t116 * __t509;
            let __t540: __F64 = __t537 - __t535;
            let __t541: __F64 = __t540 - __t538;
            let __t542: __F64 = __t121 * __t501;
            let __t544: __F64 = __t123 * __t505;
            let __t546: __F64 = __t128 * __t509;
            let __t547: __F64 = __t542 + __t544;
            let __t549: __F64 = __t546 - __t547;
            let __t550: __F64 = __v2 * __t73;
            let __t551: __F64 = __v1 * __t74;
            let __t553: __F64 = __t550 - __t551;
            let __t554: __F64 = __v0 * __t74;
            let __t555: __F64 = __v2 * __t72;
            let __t557: __F64 = __t554 - __t555;
            let __t558: __F64 = __v1 * __t72;
            let __t559: __F64 = __v0 * __t73;
            let __t561: __F64 = __t558 - __t559;
            let __t562: __F64 = __v5 * __t76;
            let __t563: __F64 = __v4 * __t78;
            let __t565: __F64 = __t562 - __t563;
            let __t566: __F64 = __v3 * __t78;
            let __t567: __F64 = __v5 * __t75;
            let __t569: __F64 = __t566 - __t567;
            let __t570: __F64 = __v4 * __t75;
            let __t571: __F64 = __v3 * __t76;
            let __t573: __F64 = __t570 - __t571;
            let __t574: __F64 = __t553 + __t565;
            let __t576: __F64 = __t574 - __t534;
            let __t577: __F64 = __t557 + __t569;
            let __t579: __F64 = __t577 - __t541;
            let __t580: __F64 = __t561 + __t573;
            let __t582: __F64 = __t580 - __t549;
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
                right_side: __Vector3::new(__t576, __t579, __t582),
                psi_dot: __t55,
            }
        }
        #[inline]
        fn certification_tape(&self) -> __MaybeTape {
            __RouthTape::parse(
                "g 0;g 1;g 2;p;f 0;f 1;f 2;- 6;^ 0 2;^ 1 2;+ 8 9;* 4 10;* 2 5;* 2 12;+ 11 13;/ 14;* 0 4;* 1 4;* 3 15;* 16 18;* 17 18;* 12 18;* 18 19;* 18 20;* 18 21;+ 7 24;* 15 19;* 15 20;* 15 21;* 4 18;* 5 18;* 18 29;* 19 26;c c010000000000000;* 33 32;+ 31 34;* 20 26;* 33 36;* 21 26;* 33 38;* 20 27;* 33 40;+ 31 41;* 21 27;* 33 43;* 18 30;* 21 28;* 33 46;+ 45 47;o 22 23 25 35 37 39 42 44 48",
                &[self.a1, self.c, self.mgl],
            )
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for LagrangeTop {
        const LAGRANGIAN: &'static str = "0.5·(a1·(ω₁^2 + ω₂^2) + ω₃^2·c) - γ₃·mgl";
        const AMENDED_POTENTIAL: &'static str = "γ₃·mgl + 0.5·p_ψ^2 / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
        const PSI_DOT_AT_REST: &'static str = "p_ψ / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
    }
};
