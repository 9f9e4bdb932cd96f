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
    #[automatically_derived]
    impl ::routh::__private::Lagrangian for LagrangeTop {
        #[inline]
        fn lagrangian(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            __t22
        }
        #[inline]
        fn dl_domega(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            ::routh::__private::Vector3::new(__t26, __t29, __t15)
        }
        #[inline]
        fn dl_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t32: ::routh::__private::f64 = -__v9;
            ::routh::__private::Vector3::new(0f64, 0f64, __t32)
        }
        #[inline]
        fn d2l_domega2(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            ::routh::__private::Matrix3::new(
                __v7,
                0f64,
                0f64,
                0f64,
                __v7,
                0f64,
                0f64,
                0f64,
                __v8,
            )
        }
        #[inline]
        fn d2l_domega_dgamma(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            ::routh::__private::Matrix3::new(
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
                0f64,
            )
        }
        #[inline]
        fn energy(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t33: ::routh::__private::f64 = __v0 * __t26;
            let __t34: ::routh::__private::f64 = __v1 * __t29;
            let __t35: ::routh::__private::f64 = __t33 + __t34;
            let __t36: ::routh::__private::f64 = __t16 + __t35;
            let __t38: ::routh::__private::f64 = __t36 - __t22;
            __t38
        }
        #[inline]
        fn cyclic_momentum(
            &self,
            __omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __omega[0usize];
            let __v1: ::routh::__private::f64 = __omega[1usize];
            let __v2: ::routh::__private::f64 = __omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            __t43
        }
    }
    #[automatically_derived]
    impl ::routh::__private::Routhian for LagrangeTop {
        #[inline]
        fn psi_dot(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            __t55
        }
        #[inline]
        fn routhian(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t57: ::routh::__private::f64 = __t53 * __t55;
            let __t60: ::routh::__private::f64 = (-0.5f64) * __t57;
            let __t61: ::routh::__private::f64 = __t22 + __t60;
            __t61
        }
        #[inline]
        fn dr_domega(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t69: ::routh::__private::f64 = __v3 * __v7;
            let __t72: ::routh::__private::f64 = __v4 * __v7;
            let __t169: ::routh::__private::f64 = __t55 * __t69;
            let __t170: ::routh::__private::f64 = __t26 + __t169;
            let __t171: ::routh::__private::f64 = __t55 * __t72;
            let __t172: ::routh::__private::f64 = __t29 + __t171;
            let __t173: ::routh::__private::f64 = __t48 * __t55;
            let __t174: ::routh::__private::f64 = __t15 + __t173;
            ::routh::__private::Vector3::new(__t170, __t172, __t174)
        }
        #[inline]
        fn dr_dgamma(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Vector3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t69: ::routh::__private::f64 = __v3 * __v7;
            let __t72: ::routh::__private::f64 = __v4 * __v7;
            let __t163: ::routh::__private::f64 = __t55 * __t55;
            let __t175: ::routh::__private::f64 = __t26 * __t55;
            let __t176: ::routh::__private::f64 = __t69 * __t163;
            let __t178: ::routh::__private::f64 = __t175 + __t176;
            let __t179: ::routh::__private::f64 = __t29 * __t55;
            let __t180: ::routh::__private::f64 = __t72 * __t163;
            let __t182: ::routh::__private::f64 = __t179 + __t180;
            let __t183: ::routh::__private::f64 = __t15 * __t55;
            let __t184: ::routh::__private::f64 = __t183 - __v9;
            let __t185: ::routh::__private::f64 = __t48 * __t163;
            let __t187: ::routh::__private::f64 = __t184 + __t185;
            ::routh::__private::Vector3::new(__t178, __t182, __t187)
        }
        #[inline]
        fn dr_dp(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t55: ::routh::__private::f64 = __t53 / __t50;
            let __t238: ::routh::__private::f64 = -__t55;
            __t238
        }
        #[inline]
        fn d2r_domega2(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t69: ::routh::__private::f64 = __v3 * __v7;
            let __t72: ::routh::__private::f64 = __v4 * __v7;
            let __t102: ::routh::__private::f64 = __t54 * __t69;
            let __t103: ::routh::__private::f64 = __t54 * __t72;
            let __t104: ::routh::__private::f64 = __t48 * __t54;
            let __t108: ::routh::__private::f64 = __t69 * __t102;
            let __t110: ::routh::__private::f64 = __v7 - __t108;
            let __t111: ::routh::__private::f64 = __t72 * __t102;
            let __t112: ::routh::__private::f64 = -__t111;
            let __t113: ::routh::__private::f64 = __t48 * __t102;
            let __t114: ::routh::__private::f64 = -__t113;
            let __t123: ::routh::__private::f64 = __t72 * __t103;
            let __t125: ::routh::__private::f64 = __v7 - __t123;
            let __t126: ::routh::__private::f64 = __t48 * __t103;
            let __t127: ::routh::__private::f64 = -__t126;
            let __t135: ::routh::__private::f64 = __t48 * __t104;
            let __t137: ::routh::__private::f64 = __v8 - __t135;
            ::routh::__private::Matrix3::new(
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
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t55: ::routh::__private::f64 = __t53 * __t54;
            let __t69: ::routh::__private::f64 = __v3 * __v7;
            let __t72: ::routh::__private::f64 = __v4 * __v7;
            let __t102: ::routh::__private::f64 = __t54 * __t69;
            let __t103: ::routh::__private::f64 = __t54 * __t72;
            let __t104: ::routh::__private::f64 = __t48 * __t54;
            let __t169: ::routh::__private::f64 = __t55 * __t69;
            let __t171: ::routh::__private::f64 = __t55 * __t72;
            let __t173: ::routh::__private::f64 = __t48 * __t55;
            let __t189: ::routh::__private::f64 = 2f64 * __t169;
            let __t190: ::routh::__private::f64 = __t26 + __t189;
            let __t191: ::routh::__private::f64 = 2f64 * __t171;
            let __t192: ::routh::__private::f64 = __t29 + __t191;
            let __t193: ::routh::__private::f64 = 2f64 * __t173;
            let __t194: ::routh::__private::f64 = __t15 + __t193;
            let __t198: ::routh::__private::f64 = __v7 * __t55;
            let __t199: ::routh::__private::f64 = __t102 * __t190;
            let __t201: ::routh::__private::f64 = __t198 - __t199;
            let __t202: ::routh::__private::f64 = __t102 * __t192;
            let __t203: ::routh::__private::f64 = -__t202;
            let __t204: ::routh::__private::f64 = __t102 * __t194;
            let __t205: ::routh::__private::f64 = -__t204;
            let __t206: ::routh::__private::f64 = __t103 * __t190;
            let __t207: ::routh::__private::f64 = -__t206;
            let __t208: ::routh::__private::f64 = __t103 * __t192;
            let __t210: ::routh::__private::f64 = __t198 - __t208;
            let __t211: ::routh::__private::f64 = __t103 * __t194;
            let __t212: ::routh::__private::f64 = -__t211;
            let __t213: ::routh::__private::f64 = __t104 * __t190;
            let __t214: ::routh::__private::f64 = -__t213;
            let __t215: ::routh::__private::f64 = __t104 * __t192;
            let __t216: ::routh::__private::f64 = -__t215;
            let __t217: ::routh::__private::f64 = __v8 * __t55;
            let __t218: ::routh::__private::f64 = __t104 * __t194;
            let __t220: ::routh::__private::f64 = __t217 - __t218;
            ::routh::__private::Matrix3::new(
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
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::Matrix3<::routh::__private::f64> {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t55: ::routh::__private::f64 = __t53 * __t54;
            let __t69: ::routh::__private::f64 = __v3 * __v7;
            let __t72: ::routh::__private::f64 = __v4 * __v7;
            let __t163: ::routh::__private::f64 = __t55 * __t55;
            let __t169: ::routh::__private::f64 = __t55 * __t69;
            let __t171: ::routh::__private::f64 = __t55 * __t72;
            let __t173: ::routh::__private::f64 = __t48 * __t55;
            let __t189: ::routh::__private::f64 = 2f64 * __t169;
            let __t190: ::routh::__private::f64 = __t26 + __t189;
            let __t191: ::routh::__private::f64 = 2f64 * __t171;
            let __t192: ::routh::__private::f64 = __t29 + __t191;
            let __t193: ::routh::__private::f64 = 2f64 * __t173;
            let __t194: ::routh::__private::f64 = __t15 + __t193;
            let __t195: ::routh::__private::f64 = __t54 * __t190;
            let __t196: ::routh::__private::f64 = __t54 * __t192;
            let __t197: ::routh::__private::f64 = __t54 * __t194;
            let __t221: ::routh::__private::f64 = __v7 * __t163;
            let __t222: ::routh::__private::f64 = __t190 * __t195;
            let __t224: ::routh::__private::f64 = __t221 - __t222;
            let __t225: ::routh::__private::f64 = __t192 * __t195;
            let __t226: ::routh::__private::f64 = -__t225;
            let __t227: ::routh::__private::f64 = __t194 * __t195;
            let __t228: ::routh::__private::f64 = -__t227;
            let __t229: ::routh::__private::f64 = __t192 * __t196;
            let __t231: ::routh::__private::f64 = __t221 - __t229;
            let __t232: ::routh::__private::f64 = __t194 * __t196;
            let __t233: ::routh::__private::f64 = -__t232;
            let __t234: ::routh::__private::f64 = __v8 * __t163;
            let __t235: ::routh::__private::f64 = __t194 * __t197;
            let __t237: ::routh::__private::f64 = __t234 - __t235;
            ::routh::__private::Matrix3::new(
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
        fn amended_potential(
            &self,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::f64 {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t239: ::routh::__private::f64 = __v6 / __t50;
            let __t241: ::routh::__private::f64 = __v6 * __t239;
            let __t243: ::routh::__private::f64 = (-0.5f64) * __t241;
            let __t244: ::routh::__private::f64 = __t243 - __t19;
            let __t398: ::routh::__private::f64 = -__t244;
            __t398
        }
        #[inline]
        fn bundle(
            &self,
            __big_omega: &::routh::__private::Vector3<::routh::__private::f64>,
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::RouthBundle {
            let __v0: ::routh::__private::f64 = __big_omega[0usize];
            let __v1: ::routh::__private::f64 = __big_omega[1usize];
            let __v2: ::routh::__private::f64 = __big_omega[2usize];
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t11: ::routh::__private::f64 = __v0 * __v0;
            let __t12: ::routh::__private::f64 = __v1 * __v1;
            let __t13: ::routh::__private::f64 = __t11 + __t12;
            let __t14: ::routh::__private::f64 = __v7 * __t13;
            let __t15: ::routh::__private::f64 = __v2 * __v8;
            let __t16: ::routh::__private::f64 = __v2 * __t15;
            let __t17: ::routh::__private::f64 = __t14 + __t16;
            let __t18: ::routh::__private::f64 = 0.5f64 * __t17;
            let __t19: ::routh::__private::f64 = __v5 * __v9;
            let __t22: ::routh::__private::f64 = __t18 - __t19;
            let __t26: ::routh::__private::f64 = __v0 * __v7;
            let __t29: ::routh::__private::f64 = __v1 * __v7;
            let __t39: ::routh::__private::f64 = __v3 * __t26;
            let __t40: ::routh::__private::f64 = __v4 * __t29;
            let __t41: ::routh::__private::f64 = __v5 * __t15;
            let __t42: ::routh::__private::f64 = __t39 + __t40;
            let __t43: ::routh::__private::f64 = __t41 + __t42;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t53: ::routh::__private::f64 = __v6 - __t43;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t55: ::routh::__private::f64 = __t53 * __t54;
            let __t57: ::routh::__private::f64 = __t53 * __t55;
            let __t60: ::routh::__private::f64 = (-0.5f64) * __t57;
            let __t61: ::routh::__private::f64 = __t22 + __t60;
            let __t69: ::routh::__private::f64 = __v3 * __v7;
            let __t72: ::routh::__private::f64 = __v4 * __v7;
            let __t102: ::routh::__private::f64 = __t54 * __t69;
            let __t103: ::routh::__private::f64 = __t54 * __t72;
            let __t104: ::routh::__private::f64 = __t48 * __t54;
            let __t108: ::routh::__private::f64 = __t69 * __t102;
            let __t110: ::routh::__private::f64 = __v7 - __t108;
            let __t111: ::routh::__private::f64 = __t72 * __t102;
            let __t112: ::routh::__private::f64 = -__t111;
            let __t113: ::routh::__private::f64 = __t48 * __t102;
            let __t114: ::routh::__private::f64 = -__t113;
            let __t123: ::routh::__private::f64 = __t72 * __t103;
            let __t125: ::routh::__private::f64 = __v7 - __t123;
            let __t126: ::routh::__private::f64 = __t48 * __t103;
            let __t127: ::routh::__private::f64 = -__t126;
            let __t135: ::routh::__private::f64 = __t48 * __t104;
            let __t137: ::routh::__private::f64 = __v8 - __t135;
            let __t163: ::routh::__private::f64 = __t55 * __t55;
            let __t169: ::routh::__private::f64 = __t55 * __t69;
            let __t170: ::routh::__private::f64 = __t26 + __t169;
            let __t171: ::routh::__private::f64 = __t55 * __t72;
            let __t172: ::routh::__private::f64 = __t29 + __t171;
            let __t173: ::routh::__private::f64 = __t48 * __t55;
            let __t174: ::routh::__private::f64 = __t15 + __t173;
            let __t175: ::routh::__private::f64 = __t26 * __t55;
            let __t176: ::routh::__private::f64 = __t69 * __t163;
            let __t178: ::routh::__private::f64 = __t175 + __t176;
            let __t179: ::routh::__private::f64 = __t29 * __t55;
            let __t180: ::routh::__private::f64 = __t72 * __t163;
            let __t182: ::routh::__private::f64 = __t179 + __t180;
            let __t183: ::routh::__private::f64 = __t15 * __t55;
            let __t184: ::routh::__private::f64 = __t183 - __v9;
            let __t185: ::routh::__private::f64 = __t48 * __t163;
            let __t187: ::routh::__private::f64 = __t184 + __t185;
            let __t189: ::routh::__private::f64 = 2f64 * __t169;
            let __t190: ::routh::__private::f64 = __t26 + __t189;
            let __t191: ::routh::__private::f64 = 2f64 * __t171;
            let __t192: ::routh::__private::f64 = __t29 + __t191;
            let __t193: ::routh::__private::f64 = 2f64 * __t173;
            let __t194: ::routh::__private::f64 = __t15 + __t193;
            let __t195: ::routh::__private::f64 = __t54 * __t190;
            let __t196: ::routh::__private::f64 = __t54 * __t192;
            let __t197: ::routh::__private::f64 = __t54 * __t194;
            let __t198: ::routh::__private::f64 = __v7 * __t55;
            let __t199: ::routh::__private::f64 = __t102 * __t190;
            let __t201: ::routh::__private::f64 = __t198 - __t199;
            let __t202: ::routh::__private::f64 = __t102 * __t192;
            let __t203: ::routh::__private::f64 = -__t202;
            let __t204: ::routh::__private::f64 = __t102 * __t194;
            let __t205: ::routh::__private::f64 = -__t204;
            let __t206: ::routh::__private::f64 = __t103 * __t190;
            let __t207: ::routh::__private::f64 = -__t206;
            let __t208: ::routh::__private::f64 = __t103 * __t192;
            let __t210: ::routh::__private::f64 = __t198 - __t208;
            let __t211: ::routh::__private::f64 = __t103 * __t194;
            let __t212: ::routh::__private::f64 = -__t211;
            let __t213: ::routh::__private::f64 = __t104 * __t190;
            let __t214: ::routh::__private::f64 = -__t213;
            let __t215: ::routh::__private::f64 = __t104 * __t192;
            let __t216: ::routh::__private::f64 = -__t215;
            let __t217: ::routh::__private::f64 = __v8 * __t55;
            let __t218: ::routh::__private::f64 = __t104 * __t194;
            let __t220: ::routh::__private::f64 = __t217 - __t218;
            let __t221: ::routh::__private::f64 = __v7 * __t163;
            let __t222: ::routh::__private::f64 = __t190 * __t195;
            let __t224: ::routh::__private::f64 = __t221 - __t222;
            let __t225: ::routh::__private::f64 = __t192 * __t195;
            let __t226: ::routh::__private::f64 = -__t225;
            let __t227: ::routh::__private::f64 = __t194 * __t195;
            let __t228: ::routh::__private::f64 = -__t227;
            let __t229: ::routh::__private::f64 = __t192 * __t196;
            let __t231: ::routh::__private::f64 = __t221 - __t229;
            let __t232: ::routh::__private::f64 = __t194 * __t196;
            let __t233: ::routh::__private::f64 = -__t232;
            let __t234: ::routh::__private::f64 = __v8 * __t163;
            let __t235: ::routh::__private::f64 = __t194 * __t197;
            let __t237: ::routh::__private::f64 = __t234 - __t235;
            let __t238: ::routh::__private::f64 = -__t55;
            ::routh::__private::RouthBundle {
                routhian: __t61,
                psi_dot: __t55,
                dr_domega: ::routh::__private::Vector3::new(__t170, __t172, __t174),
                dr_dgamma: ::routh::__private::Vector3::new(__t178, __t182, __t187),
                dr_dp: __t238,
                d2r_domega2: ::routh::__private::Matrix3::new(
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
                d2r_domega_dgamma: ::routh::__private::Matrix3::new(
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
                d2r_dgamma2: ::routh::__private::Matrix3::new(
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
            __gamma: &::routh::__private::Vector3<::routh::__private::f64>,
            __p_psi: ::routh::__private::f64,
        ) -> ::routh::__private::GyroscopicSystem {
            let __v3: ::routh::__private::f64 = __gamma[0usize];
            let __v4: ::routh::__private::f64 = __gamma[1usize];
            let __v5: ::routh::__private::f64 = __gamma[2usize];
            let __v6: ::routh::__private::f64 = __p_psi;
            let __v7: ::routh::__private::f64 = self.a1;
            let __v8: ::routh::__private::f64 = self.c;
            let __v9: ::routh::__private::f64 = self.mgl;
            let __t44: ::routh::__private::f64 = __v3 * __v3;
            let __t45: ::routh::__private::f64 = __v4 * __v4;
            let __t46: ::routh::__private::f64 = __t44 + __t45;
            let __t47: ::routh::__private::f64 = __v7 * __t46;
            let __t48: ::routh::__private::f64 = __v5 * __v8;
            let __t49: ::routh::__private::f64 = __v5 * __t48;
            let __t50: ::routh::__private::f64 = __t47 + __t49;
            let __t54: ::routh::__private::f64 = 1.0f64 / __t50;
            let __t69: ::routh::__private::f64 = __v3 * __v7;
            let __t72: ::routh::__private::f64 = __v4 * __v7;
            let __t102: ::routh::__private::f64 = __t54 * __t69;
            let __t103: ::routh::__private::f64 = __t54 * __t72;
            let __t104: ::routh::__private::f64 = __t48 * __t54;
            let __t108: ::routh::__private::f64 = __t69 * __t102;
            let __t110: ::routh::__private::f64 = __v7 - __t108;
            let __t111: ::routh::__private::f64 = __t72 * __t102;
            let __t112: ::routh::__private::f64 = -__t111;
            let __t113: ::routh::__private::f64 = __t48 * __t102;
            let __t114: ::routh::__private::f64 = -__t113;
            let __t123: ::routh::__private::f64 = __t72 * __t103;
            let __t125: ::routh::__private::f64 = __v7 - __t123;
            let __t126: ::routh::__private::f64 = __t48 * __t103;
            let __t127: ::routh::__private::f64 = -__t126;
            let __t135: ::routh::__private::f64 = __t48 * __t104;
            let __t137: ::routh::__private::f64 = __v8 - __t135;
            let __t239: ::routh::__private::f64 = __v6 * __t54;
            let __t313: ::routh::__private::f64 = __t239 * __t239;
            let __t317: ::routh::__private::f64 = __t69 * __t239;
            let __t318: ::routh::__private::f64 = __t72 * __t239;
            let __t319: ::routh::__private::f64 = __t48 * __t239;
            let __t320: ::routh::__private::f64 = __t69 * __t313;
            let __t322: ::routh::__private::f64 = __t72 * __t313;
            let __t324: ::routh::__private::f64 = __t48 * __t313;
            let __t326: ::routh::__private::f64 = __t324 - __v9;
            let __t331: ::routh::__private::f64 = __t54 * __t317;
            let __t333: ::routh::__private::f64 = __t54 * __t318;
            let __t335: ::routh::__private::f64 = __t54 * __t319;
            let __t337: ::routh::__private::f64 = __v7 * __t239;
            let __t338: ::routh::__private::f64 = __t102 * __t317;
            let __t340: ::routh::__private::f64 = (-2f64) * __t338;
            let __t341: ::routh::__private::f64 = __t337 + __t340;
            let __t342: ::routh::__private::f64 = __t102 * __t318;
            let __t345: ::routh::__private::f64 = __t102 * __t319;
            let __t348: ::routh::__private::f64 = __t103 * __t317;
            let __t351: ::routh::__private::f64 = __t103 * __t318;
            let __t353: ::routh::__private::f64 = (-2f64) * __t351;
            let __t354: ::routh::__private::f64 = __t337 + __t353;
            let __t355: ::routh::__private::f64 = __t103 * __t319;
            let __t358: ::routh::__private::f64 = __t104 * __t317;
            let __t361: ::routh::__private::f64 = __t104 * __t318;
            let __t364: ::routh::__private::f64 = __v8 * __t239;
            let __t365: ::routh::__private::f64 = __t104 * __t319;
            let __t367: ::routh::__private::f64 = (-2f64) * __t365;
            let __t368: ::routh::__private::f64 = __t364 + __t367;
            let __t369: ::routh::__private::f64 = __v7 * __t313;
            let __t370: ::routh::__private::f64 = __t317 * __t331;
            let __t373: ::routh::__private::f64 = (-4f64) * __t370;
            let __t374: ::routh::__private::f64 = __t369 + __t373;
            let __t375: ::routh::__private::f64 = __t318 * __t331;
            let __t379: ::routh::__private::f64 = __t319 * __t331;
            let __t383: ::routh::__private::f64 = __t318 * __t333;
            let __t386: ::routh::__private::f64 = (-4f64) * __t383;
            let __t387: ::routh::__private::f64 = __t369 + __t386;
            let __t388: ::routh::__private::f64 = __t319 * __t333;
            let __t392: ::routh::__private::f64 = __v8 * __t313;
            let __t393: ::routh::__private::f64 = __t319 * __t335;
            let __t396: ::routh::__private::f64 = (-4f64) * __t393;
            let __t397: ::routh::__private::f64 = __t392 + __t396;
            let __t411: ::routh::__private::f64 = __v5 * __t341;
            let __t413: ::routh::__private::f64 = __v3 * __t345;
            let __t414: ::routh::__private::f64 = (-2f64) * __t413;
            let __t415: ::routh::__private::f64 = __t414 - __t411;
            let __t416: ::routh::__private::f64 = __v4 * __t341;
            let __t417: ::routh::__private::f64 = __v3 * __t342;
            let __t418: ::routh::__private::f64 = (-2f64) * __t417;
            let __t419: ::routh::__private::f64 = 2f64 * __t417;
            let __t420: ::routh::__private::f64 = __t416 + __t419;
            let __t421: ::routh::__private::f64 = __v5 * __t354;
            let __t422: ::routh::__private::f64 = __v4 * __t355;
            let __t423: ::routh::__private::f64 = (-2f64) * __t422;
            let __t424: ::routh::__private::f64 = 2f64 * __t422;
            let __t425: ::routh::__private::f64 = __t421 + __t424;
            let __t432: ::routh::__private::f64 = __v4 * __t348;
            let __t433: ::routh::__private::f64 = (-2f64) * __t432;
            let __t434: ::routh::__private::f64 = __v3 * __t354;
            let __t436: ::routh::__private::f64 = __t433 - __t434;
            let __t437: ::routh::__private::f64 = __v5 * __t361;
            let __t438: ::routh::__private::f64 = (-2f64) * __t437;
            let __t439: ::routh::__private::f64 = __v4 * __t368;
            let __t441: ::routh::__private::f64 = __t438 - __t439;
            let __t442: ::routh::__private::f64 = __v5 * __t358;
            let __t443: ::routh::__private::f64 = (-2f64) * __t442;
            let __t444: ::routh::__private::f64 = 2f64 * __t442;
            let __t445: ::routh::__private::f64 = __v3 * __t368;
            let __t446: ::routh::__private::f64 = __t444 + __t445;
            let __t456: ::routh::__private::f64 = __t423 - __t421;
            let __t457: ::routh::__private::f64 = 2f64 * __t437;
            let __t458: ::routh::__private::f64 = __t439 + __t457;
            let __t459: ::routh::__private::f64 = 2f64 * __t413;
            let __t460: ::routh::__private::f64 = __t411 + __t459;
            let __t464: ::routh::__private::f64 = __t443 - __t445;
            let __t466: ::routh::__private::f64 = __t418 - __t416;
            let __t467: ::routh::__private::f64 = 2f64 * __t432;
            let __t468: ::routh::__private::f64 = __t434 + __t467;
            let __t471: ::routh::__private::f64 = __t415 + __t456;
            let __t472: ::routh::__private::f64 = __t319 + __t471;
            let __t473: ::routh::__private::f64 = 0.5f64 * __t472;
            let __t474: ::routh::__private::f64 = __t420 + __t458;
            let __t475: ::routh::__private::f64 = __t474 - __t318;
            let __t476: ::routh::__private::f64 = 0.5f64 * __t475;
            let __t477: ::routh::__private::f64 = __t425 + __t460;
            let __t478: ::routh::__private::f64 = __t477 - __t319;
            let __t479: ::routh::__private::f64 = 0.5f64 * __t478;
            let __t480: ::routh::__private::f64 = __t436 + __t464;
            let __t481: ::routh::__private::f64 = __t317 + __t480;
            let __t482: ::routh::__private::f64 = 0.5f64 * __t481;
            let __t483: ::routh::__private::f64 = __t441 + __t466;
            let __t484: ::routh::__private::f64 = __t318 + __t483;
            let __t485: ::routh::__private::f64 = 0.5f64 * __t484;
            let __t486: ::routh::__private::f64 = __t446 + __t468;
            let __t487: ::routh::__private::f64 = __t486 - __t317;
            let __t488: ::routh::__private::f64 = 0.5f64 * __t487;
            let __t489: ::routh::__private::f64 = __v3 * __t320;
            let __t490: ::routh::__private::f64 = __v4 * __t322;
            let __t491: ::routh::__private::f64 = __v5 * __t326;
            let __t492: ::routh::__private::f64 = __t489 + __t490;
            let __t493: ::routh::__private::f64 = __t491 + __t492;
            let __t495: ::routh::__private::f64 = __t493 - __t374;
            let __t497: ::routh::__private::f64 = __t493 - __t387;
            let __t499: ::routh::__private::f64 = __t493 - __t397;
            let __t500: ::routh::__private::f64 = __v5 * __t375;
            let __t501: ::routh::__private::f64 = 4f64 * __t500;
            let __t502: ::routh::__private::f64 = __v4 * __t379;
            let __t503: ::routh::__private::f64 = 4f64 * __t502;
            let __t504: ::routh::__private::f64 = (-4f64) * __t502;
            let __t505: ::routh::__private::f64 = __t501 + __t504;
            let __t506: ::routh::__private::f64 = __v5 * __t497;
            let __t507: ::routh::__private::f64 = __v4 * __t388;
            let __t509: ::routh::__private::f64 = (-4f64) * __t507;
            let __t510: ::routh::__private::f64 = __t506 + __t509;
            let __t511: ::routh::__private::f64 = __v5 * __t388;
            let __t512: ::routh::__private::f64 = 4f64 * __t511;
            let __t513: ::routh::__private::f64 = __v4 * __t499;
            let __t515: ::routh::__private::f64 = __t512 - __t513;
            let __t516: ::routh::__private::f64 = __v5 * __t495;
            let __t518: ::routh::__private::f64 = __v3 * __t379;
            let __t519: ::routh::__private::f64 = 4f64 * __t518;
            let __t520: ::routh::__private::f64 = __t519 - __t516;
            let __t521: ::routh::__private::f64 = (-4f64) * __t500;
            let __t522: ::routh::__private::f64 = __v3 * __t388;
            let __t523: ::routh::__private::f64 = 4f64 * __t522;
            let __t524: ::routh::__private::f64 = __t521 + __t523;
            let __t525: ::routh::__private::f64 = __v5 * __t379;
            let __t527: ::routh::__private::f64 = (-4f64) * __t525;
            let __t528: ::routh::__private::f64 = __v3 * __t499;
            let __t529: ::routh::__private::f64 = __t527 + __t528;
            let __t530: ::routh::__private::f64 = __v4 * __t495;
            let __t531: ::routh::__private::f64 = __v3 * __t375;
            let __t533: ::routh::__private::f64 = (-4f64) * __t531;
            let __t534: ::routh::__private::f64 = __t530 + __t533;
            let __t535: ::routh::__private::f64 = __v4 * __t375;
            let __t536: ::routh::__private::f64 = 4f64 * __t535;
            let __t537: ::routh::__private::f64 = __v3 * __t497;
            let __t539: ::routh::__private::f64 = __t536 - __t537;
            let __t540: ::routh::__private::f64 = (-4f64) * __t522;
            let __t541: ::routh::__private::f64 = __t503 + __t540;
            let __t542: ::routh::__private::f64 = __v5 * __t510;
            let __t543: ::routh::__private::f64 = __v4 * __t515;
            let __t545: ::routh::__private::f64 = __t542 - __t543;
            let __t546: ::routh::__private::f64 = __v5 * __t505;
            let __t548: ::routh::__private::f64 = __v3 * __t515;
            let __t549: ::routh::__private::f64 = __t548 - __t546;
            let __t550: ::routh::__private::f64 = __v4 * __t505;
            let __t551: ::routh::__private::f64 = __v3 * __t510;
            let __t553: ::routh::__private::f64 = __t550 - __t551;
            let __t554: ::routh::__private::f64 = __v5 * __t524;
            let __t555: ::routh::__private::f64 = __v4 * __t529;
            let __t557: ::routh::__private::f64 = __t554 - __t555;
            let __t558: ::routh::__private::f64 = __v5 * __t520;
            let __t560: ::routh::__private::f64 = __v3 * __t529;
            let __t561: ::routh::__private::f64 = __t560 - __t558;
            let __t562: ::routh::__private::f64 = __v4 * __t520;
            let __t563: ::routh::__private::f64 = __v3 * __t524;
            let __t565: ::routh::__private::f64 = __t562 - __t563;
            let __t566: ::routh::__private::f64 = __v5 * __t539;
            let __t567: ::routh::__private::f64 = __v4 * __t541;
            let __t569: ::routh::__private::f64 = __t566 - __t567;
            let __t570: ::routh::__private::f64 = __v5 * __t534;
            let __t572: ::routh::__private::f64 = __v3 * __t541;
            let __t573: ::routh::__private::f64 = __t572 - __t570;
            let __t574: ::routh::__private::f64 = __v4 * __t534;
            let __t575: ::routh::__private::f64 = __v3 * __t539;
            let __t577: ::routh::__private::f64 = __t574 - __t575;
            ::routh::__private::GyroscopicSystem {
                a: ::routh::__private::Matrix3::new(
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
                g: ::routh::__private::Matrix3::new(
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
                c: ::routh::__private::Matrix3::new(
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
