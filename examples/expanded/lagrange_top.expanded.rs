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
            let __t69: __F64 = __v3 * __v7;
            let __t72: __F64 = __v4 * __v7;
            let __t169: __F64 = __t55 * __t69;
            let __t170: __F64 = __t26 + __t169;
            let __t171: __F64 = __t55 * __t72;
            let __t172: __F64 = __t29 + __t171;
            let __t173: __F64 = __t48 * __t55;
            let __t174: __F64 = __t15 + __t173;
            __Vector3::new(__t170, __t172, __t174)
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
            let __t69: __F64 = __v3 * __v7;
            let __t72: __F64 = __v4 * __v7;
            let __t163: __F64 = __t55 * __t55;
            let __t175: __F64 = __t26 * __t55;
            let __t176: __F64 = __t69 * __t163;
            let __t178: __F64 = __t175 + __t176;
            let __t179: __F64 = __t29 * __t55;
            let __t180: __F64 = __t72 * __t163;
            let __t182: __F64 = __t179 + __t180;
            let __t183: __F64 = __t15 * __t55;
            let __t184: __F64 = __t183 - __v9;
            let __t185: __F64 = __t48 * __t163;
            let __t187: __F64 = __t184 + __t185;
            __Vector3::new(__t178, __t182, __t187)
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
            let __t238: __F64 = -__t55;
            __t238
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
            let __t69: __F64 = __v3 * __v7;
            let __t72: __F64 = __v4 * __v7;
            let __t102: __F64 = __t54 * __t69;
            let __t103: __F64 = __t54 * __t72;
            let __t104: __F64 = __t48 * __t54;
            let __t108: __F64 = __t69 * __t102;
            let __t110: __F64 = __v7 - __t108;
            let __t111: __F64 = __t72 * __t102;
            let __t112: __F64 = -__t111;
            let __t113: __F64 = __t48 * __t102;
            let __t114: __F64 = -__t113;
            let __t123: __F64 = __t72 * __t103;
            let __t125: __F64 = __v7 - __t123;
            let __t126: __F64 = __t48 * __t103;
            let __t127: __F64 = -__t126;
            let __t135: __F64 = __t48 * __t104;
            let __t137: __F64 = __v8 - __t135;
            __Matrix3::new(
                __t110,
                __t112,
                __t114,
                __t112,
                __t125,
                __t127,
                __t114,
                __t127,
                __t137,
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
            let __t69: __F64 = __v3 * __v7;
            let __t72: __F64 = __v4 * __v7;
            let __t102: __F64 = __t54 * __t69;
            let __t103: __F64 = __t54 * __t72;
            let __t104: __F64 = __t48 * __t54;
            let __t169: __F64 = __t55 * __t69;
            let __t171: __F64 = __t55 * __t72;
            let __t173: __F64 = __t48 * __t55;
            let __t189: __F64 = 2f64 * __t169;
            let __t190: __F64 = __t26 + __t189;
            let __t191: __F64 = 2f64 * __t171;
            let __t192: __F64 = __t29 + __t191;
            let __t193: __F64 = 2f64 * __t173;
            let __t194: __F64 = __t15 + __t193;
            let __t198: __F64 = __v7 * __t55;
            let __t199: __F64 = __t102 * __t190;
            let __t201: __F64 = __t198 - __t199;
            let __t202: __F64 = __t102 * __t192;
            let __t203: __F64 = -__t202;
            let __t204: __F64 = __t102 * __t194;
            let __t205: __F64 = -__t204;
            let __t206: __F64 = __t103 * __t190;
            let __t207: __F64 = -__t206;
            let __t208: __F64 = __t103 * __t192;
            let __t210: __F64 = __t198 - __t208;
            let __t211: __F64 = __t103 * __t194;
            let __t212: __F64 = -__t211;
            let __t213: __F64 = __t104 * __t190;
            let __t214: __F64 = -__t213;
            let __t215: __F64 = __t104 * __t192;
            let __t216: __F64 = -__t215;
            let __t217: __F64 = __v8 * __t55;
            let __t218: __F64 = __t104 * __t194;
            let __t220: __F64 = __t217 - __t218;
            __Matrix3::new(
                __t201,
                __t203,
                __t205,
                __t207,
                __t210,
                __t212,
                __t214,
                __t216,
                __t220,
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
            let __t69: __F64 = __v3 * __v7;
            let __t72: __F64 = __v4 * __v7;
            let __t163: __F64 = __t55 * __t55;
            let __t169: __F64 = __t55 * __t69;
            let __t171: __F64 = __t55 * __t72;
            let __t173: __F64 = __t48 * __t55;
            let __t189: __F64 = 2f64 * __t169;
            let __t190: __F64 = __t26 + __t189;
            let __t191: __F64 = 2f64 * __t171;
            let __t192: __F64 = __t29 + __t191;
            let __t193: __F64 = 2f64 * __t173;
            let __t194: __F64 = __t15 + __t193;
            let __t195: __F64 = __t54 * __t190;
            let __t196: __F64 = __t54 * __t192;
            let __t197: __F64 = __t54 * __t194;
            let __t221: __F64 = __v7 * __t163;
            let __t222: __F64 = __t190 * __t195;
            let __t224: __F64 = __t221 - __t222;
            let __t225: __F64 = __t192 * __t195;
            let __t226: __F64 = -__t225;
            let __t227: __F64 = __t194 * __t195;
            let __t228: __F64 = -__t227;
            let __t229: __F64 = __t192 * __t196;
            let __t231: __F64 = __t221 - __t229;
            let __t232: __F64 = __t194 * __t196;
            let __t233: __F64 = -__t232;
            let __t234: __F64 = __v8 * __t163;
            let __t235: __F64 = __t194 * __t197;
            let __t237: __F64 = __t234 - __t235;
            __Matrix3::new(
                __t224,
                __t226,
                __t228,
                __t226,
                __t231,
                __t233,
                __t228,
                __t233,
                __t237,
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
            let __t239: __F64 = __v6 / __t50;
            let __t241: __F64 = __v6 * __t239;
            let __t243: __F64 = (-0.5f64) * __t241;
            let __t244: __F64 = __t243 - __t19;
            let __t398: __F64 = -__t244;
            __t398
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
            let __t69: __F64 = __v3 * __v7;
            let __t72: __F64 = __v4 * __v7;
            let __t102: __F64 = __t54 * __t69;
            let __t103: __F64 = __t54 * __t72;
            let __t104: __F64 = __t48 * __t54;
            let __t108: __F64 = __t69 * __t102;
            let __t110: __F64 = __v7 - __t108;
            let __t111: __F64 = __t72 * __t102;
            let __t112: __F64 = -__t111;
            let __t113: __F64 = __t48 * __t102;
            let __t114: __F64 = -__t113;
            let __t123: __F64 = __t72 * __t103;
            let __t125: __F64 = __v7 - __t123;
            let __t126: __F64 = __t48 * __t103;
            let __t127: __F64 = -__t126;
            let __t135: __F64 = __t48 * __t104;
            let __t137: __F64 = __v8 - __t135;
            let __t163: __F64 = __t55 * __t55;
            let __t169: __F64 = __t55 * __t69;
            let __t170: __F64 = __t26 + __t169;
            let __t171: __F64 = __t55 * __t72;
            let __t172: __F64 = __t29 + __t171;
            let __t173: __F64 = __t48 * __t55;
            let __t174: __F64 = __t15 + __t173;
            let __t175: __F64 = __t26 * __t55;
            let __t176: __F64 = __t69 * __t163;
            let __t178: __F64 = __t175 + __t176;
            let __t179: __F64 = __t29 * __t55;
            let __t180: __F64 = __t72 * __t163;
            let __t182: __F64 = __t179 + __t180;
            let __t183: __F64 = __t15 * __t55;
            let __t184: __F64 = __t183 - __v9;
            let __t185: __F64 = __t48 * __t163;
            let __t187: __F64 = __t184 + __t185;
            let __t189: __F64 = 2f64 * __t169;
            let __t190: __F64 = __t26 + __t189;
            let __t191: __F64 = 2f64 * __t171;
            let __t192: __F64 = __t29 + __t191;
            let __t193: __F64 = 2f64 * __t173;
            let __t194: __F64 = __t15 + __t193;
            let __t195: __F64 = __t54 * __t190;
            let __t196: __F64 = __t54 * __t192;
            let __t197: __F64 = __t54 * __t194;
            let __t198: __F64 = __v7 * __t55;
            let __t199: __F64 = __t102 * __t190;
            let __t201: __F64 = __t198 - __t199;
            let __t202: __F64 = __t102 * __t192;
            let __t203: __F64 = -__t202;
            let __t204: __F64 = __t102 * __t194;
            let __t205: __F64 = -__t204;
            let __t206: __F64 = __t103 * __t190;
            let __t207: __F64 = -__t206;
            let __t208: __F64 = __t103 * __t192;
            let __t210: __F64 = __t198 - __t208;
            let __t211: __F64 = __t103 * __t194;
            let __t212: __F64 = -__t211;
            let __t213: __F64 = __t104 * __t190;
            let __t214: __F64 = -__t213;
            let __t215: __F64 = __t104 * __t192;
            let __t216: __F64 = -__t215;
            let __t217: __F64 = __v8 * __t55;
            let __t218: __F64 = __t104 * __t194;
            let __t220: __F64 = __t217 - __t218;
            let __t221: __F64 = __v7 * __t163;
            let __t222: __F64 = __t190 * __t195;
            let __t224: __F64 = __t221 - __t222;
            let __t225: __F64 = __t192 * __t195;
            let __t226: __F64 = -__t225;
            let __t227: __F64 = __t194 * __t195;
            let __t228: __F64 = -__t227;
            let __t229: __F64 = __t192 * __t196;
            let __t231: __F64 = __t221 - __t229;
            let __t232: __F64 = __t194 * __t196;
            let __t233: __F64 = -__t232;
            let __t234: __F64 = __v8 * __t163;
            let __t235: __F64 = __t194 * __t197;
            let __t237: __F64 = __t234 - __t235;
            let __t238: __F64 = -__t55;
            __RouthBundle {
                routhian: __t61,
                psi_dot: __t55,
                dr_domega: __Vector3::new(__t170, __t172, __t174),
                dr_dgamma: __Vector3::new(__t178, __t182, __t187),
                dr_dp: __t238,
                d2r_domega2: __Matrix3::new(
                    __t110,
                    __t112,
                    __t114,
                    __t112,
                    __t125,
                    __t127,
                    __t114,
                    __t127,
                    __t137,
                ),
                d2r_domega_dgamma: __Matrix3::new(
                    __t201,
                    __t203,
                    __t205,
                    __t207,
                    __t210,
                    __t212,
                    __t214,
                    __t216,
                    __t220,
                ),
                d2r_dgamma2: __Matrix3::new(
                    __t224,
                    __t226,
                    __t228,
                    __t226,
                    __t231,
                    __t233,
                    __t228,
                    __t233,
                    __t237,
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
            let __t69: __F64 = __v3 * __v7;
            let __t72: __F64 = __v4 * __v7;
            let __t102: __F64 = __t54 * __t69;
            let __t103: __F64 = __t54 * __t72;
            let __t104: __F64 = __t48 * __t54;
            let __t108: __F64 = __t69 * __t102;
            let __t110: __F64 = __v7 - __t108;
            let __t111: __F64 = __t72 * __t102;
            let __t112: __F64 = -__t111;
            let __t113: __F64 = __t48 * __t102;
            let __t114: __F64 = -__t113;
            let __t123: __F64 = __t72 * __t103;
            let __t125: __F64 = __v7 - __t123;
            let __t126: __F64 = __t48 * __t103;
            let __t127: __F64 = -__t126;
            let __t135: __F64 = __t48 * __t104;
            let __t137: __F64 = __v8 - __t135;
            let __t239: __F64 = __v6 * __t54;
            let __t313: __F64 = __t239 * __t239;
            let __t317: __F64 = __t69 * __t239;
            let __t318: __F64 = __t72 * __t239;
            let __t319: __F64 = __t48 * __t239;
            let __t320: __F64 = __t69 * __t313;
            let __t322: __F64 = __t72 * __t313;
            let __t324: __F64 = __t48 * __t313;
            let __t326: __F64 = __t324 - __v9;
            let __t331: __F64 = __t54 * __t317;
            let __t333: __F64 = __t54 * __t318;
            let __t335: __F64 = __t54 * __t319;
            let __t337: __F64 = __v7 * __t239;
            let __t338: __F64 = __t102 * __t317;
            let __t340: __F64 = (-2f64) * __t338;
            let __t341: __F64 = __t337 + __t340;
            let __t342: __F64 = __t102 * __t318;
            let __t345: __F64 = __t102 * __t319;
            let __t348: __F64 = __t103 * __t317;
            let __t351: __F64 = __t103 * __t318;
            let __t353: __F64 = (-2f64) * __t351;
            let __t354: __F64 = __t337 + __t353;
            let __t355: __F64 = __t103 * __t319;
            let __t358: __F64 = __t104 * __t317;
            let __t361: __F64 = __t104 * __t318;
            let __t364: __F64 = __v8 * __t239;
            let __t365: __F64 = __t104 * __t319;
            let __t367: __F64 = (-2f64) * __t365;
            let __t368: __F64 = __t364 + __t367;
            let __t369: __F64 = __v7 * __t313;
            let __t370: __F64 = __t317 * __t331;
            let __t373: __F64 = (-4f64) * __t370;
            let __t374: __F64 = __t369 + __t373;
            let __t375: __F64 = __t318 * __t331;
            let __t379: __F64 = __t319 * __t331;
            let __t383: __F64 = __t318 * __t333;
            let __t386: __F64 = (-4f64) * __t383;
            let __t387: __F64 = __t369 + __t386;
            let __t388: __F64 = __t319 * __t333;
            let __t392: __F64 = __v8 * __t313;
            let __t393: __F64 = __t319 * __t335;
            let __t396: __F64 = (-4f64) * __t393;
            let __t397: __F64 = __t392 + __t396;
            let __t411: __F64 = __v5 * __t341;
            let __t413: __F64 = __v3 * __t345;
            let __t414: __F64 = (-2f64) * __t413;
            let __t415: __F64 = __t414 - __t411;
            let __t416: __F64 = __v4 * __t341;
            let __t417: __F64 = __v3 * __t342;
            let __t418: __F64 = (-2f64) * __t417;
            let __t419: __F64 = 2f64 * __t417;
            let __t420: __F64 = __t416 + __t419;
            let __t421: __F64 = __v5 * __t354;
            let __t422: __F64 = __v4 * __t355;
            let __t423: __F64 = (-2f64) * __t422;
            let __t424: __F64 = 2f64 * __t422;
            let __t425: __F64 = __t421 + __t424;
            let __t432: __F64 = __v4 * __t348;
            let __t433: __F64 = (-2f64) * __t432;
            let __t434: __F64 = __v3 * __t354;
            let __t436: __F64 = __t433 - __t434;
            let __t437: __F64 = __v5 * __t361;
            let __t438: __F64 = (-2f64) * __t437;
            let __t439: __F64 = __v4 * __t368;
            let __t441: __F64 = __t438 - __t439;
            let __t442: __F64 = __v5 * __t358;
            let __t443: __F64 = (-2f64) * __t442;
            let __t444: __F64 = 2f64 * __t442;
            let __t445: __F64 = __v3 * __t368;
            let __t446: __F64 = __t444 + __t445;
            let __t456: __F64 = __t423 - __t421;
            let __t457: __F64 = 2f64 * __t437;
            let __t458: __F64 = __t439 + __t457;
            let __t459: __F64 = 2f64 * __t413;
            let __t460: __F64 = __t411 + __t459;
            let __t464: __F64 = __t443 - __t445;
            let __t466: __F64 = __t418 - __t416;
            let __t467: __F64 = 2f64 * __t432;
            let __t468: __F64 = __t434 + __t467;
            let __t471: __F64 = __t415 + __t456;
            let __t472: __F64 = __t319 + __t471;
            let __t473: __F64 = 0.5f64 * __t472;
            let __t474: __F64 = __t420 + __t458;
            let __t475: __F64 = __t474 - __t318;
            let __t476: __F64 = 0.5f64 * __t475;
            let __t477: __F64 = __t425 + __t460;
            let __t478: __F64 = __t477 - __t319;
            let __t479: __F64 = 0.5f64 * __t478;
            let __t480: __F64 = __t436 + __t464;
            let __t481: __F64 = __t317 + __t480;
            let __t482: __F64 = 0.5f64 * __t481;
            let __t483: __F64 = __t441 + __t466;
            let __t484: __F64 = __t318 + __t483;
            let __t485: __F64 = 0.5f64 * __t484;
            let __t486: __F64 = __t446 + __t468;
            let __t487: __F64 = __t486 - __t317;
            let __t488: __F64 = 0.5f64 * __t487;
            let __t489: __F64 = __v3 * __t320;
            let __t490: __F64 = __v4 * __t322;
            let __t491: __F64 = __v5 * __t326;
            let __t492: __F64 = __t489 + __t490;
            let __t493: __F64 = __t491 + __t492;
            let __t495: __F64 = __t493 - __t374;
            let __t497: __F64 = __t493 - __t387;
            let __t499: __F64 = __t493 - __t397;
            let __t500: __F64 = __v5 * __t375;
            let __t501: __F64 = 4f64 * __t500;
            let __t502: __F64 = __v4 * __t379;
            let __t503: __F64 = 4f64 * __t502;
            let __t504: __F64 = (-4f64) * __t502;
            let __t505: __F64 = __t501 + __t504;
            let __t506: __F64 = __v5 * __t497;
            let __t507: __F64 = __v4 * __t388;
            let __t509: __F64 = (-4f64) * __t507;
            let __t510: __F64 = __t506 + __t509;
            let __t511: __F64 = __v5 * __t388;
            let __t512: __F64 = 4f64 * __t511;
            let __t513: __F64 = __v4 * __t499;
            let __t515: __F64 = __t512 - __t513;
            let __t516: __F64 = __v5 * __t495;
            let __t518: __F64 = __v3 * __t379;
            let __t519: __F64 = 4f64 * __t518;
            let __t520: __F64 = __t519 - __t516;
            let __t521: __F64 = (-4f64) * __t500;
            let __t522: __F64 = __v3 * __t388;
            let __t523: __F64 = 4f64 * __t522;
            let __t524: __F64 = __t521 + __t523;
            let __t525: __F64 = __v5 * __t379;
            let __t527: __F64 = (-4f64) * __t525;
            let __t528: __F64 = __v3 * __t499;
            let __t529: __F64 = __t527 + __t528;
            let __t530: __F64 = __v4 * __t495;
            let __t531: __F64 = __v3 * __t375;
            let __t533: __F64 = (-4f64) * __t531;
            let __t534: __F64 = __t530 + __t533;
            let __t535: __F64 = __v4 * __t375;
            let __t536: __F64 = 4f64 * __t535;
            let __t537: __F64 = __v3 * __t497;
            let __t539: __F64 = __t536 - __t537;
            let __t540: __F64 = (-4f64) * __t522;
            let __t541: __F64 = __t503 + __t540;
            let __t542: __F64 = __v5 * __t510;
            let __t543: __F64 = __v4 * __t515;
            let __t545: __F64 = __t542 - __t543;
            let __t546: __F64 = __v5 * __t505;
            let __t548: __F64 = __v3 * __t515;
            let __t549: __F64 = __t548 - __t546;
            let __t550: __F64 = __v4 * __t505;
            let __t551: __F64 = __v3 * __t510;
            let __t553: __F64 = __t550 - __t551;
            let __t554: __F64 = __v5 * __t524;
            let __t555: __F64 = __v4 * __t529;
            let __t557: __F64 = __t554 - __t555;
            let __t558: __F64 = __v5 * __t520;
            let __t560: __F64 = __v3 * __t529;
            let __t561: __F64 = __t560 - __t558;
            let __t562: __F64 = __v4 * __t520;
            let __t563: __F64 = __v3 * __t524;
            let __t565: __F64 = __t562 - __t563;
            let __t566: __F64 = __v5 * __t539;
            let __t567: __F64 = __v4 * __t541;
            let __t569: __F64 = __t566 - __t567;
            let __t570: __F64 = __v5 * __t534;
            let __t572: __F64 = __v3 * __t541;
            let __t573: __F64 = __t572 - __t570;
            let __t574: __F64 = __v4 * __t534;
            let __t575: __F64 = __v3 * __t539;
            let __t577: __F64 = __t574 - __t575;
            __GyroscopicSystem {
                a: __Matrix3::new(
                    __t110,
                    __t112,
                    __t114,
                    __t112,
                    __t125,
                    __t127,
                    __t114,
                    __t127,
                    __t137,
                ),
                g: __Matrix3::new(
                    0f64,
                    __t473,
                    __t476,
                    __t479,
                    0f64,
                    __t482,
                    __t485,
                    __t488,
                    0f64,
                ),
                c: __Matrix3::new(
                    __t545,
                    __t549,
                    __t553,
                    __t557,
                    __t561,
                    __t565,
                    __t569,
                    __t573,
                    __t577,
                ),
            }
        }
    }
    #[automatically_derived]
    impl ::routh::__private::DerivedFormulas for LagrangeTop {
        const LAGRANGIAN: &'static str = "0.5·(a1·(ω₁^2 + ω₂^2) + ω₃^2·c) - γ₃·mgl";
        const AMENDED_POTENTIAL: &'static str = "γ₃·mgl + 0.5·p_ψ^2 / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
        const PSI_DOT_AT_REST: &'static str = "p_ψ / (a1·(γ₁^2 + γ₂^2) + γ₃^2·c)";
    }
};
